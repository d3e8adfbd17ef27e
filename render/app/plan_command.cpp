// rugosim plan render SCENE -o OUT.mp4 --chunks N: the whole job of a chunked render
// (docs/scale-out.md) printed as commands — the checkpoint pass, one render per chunk, the join —
// and as ready-to-submit recipes for GNU parallel, Slurm (sbatch with an array and afterok
// dependencies) and a Kubernetes Indexed Job. It runs nothing; it reads the scene only to count
// the clip's frames and check what the chunks will check.
#include <cstddef>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "render/app/commands.h"
#include "render/app/render_chunk.h"
#include "render/app/run_length.h"
#include "render/app/scene_input.h"

namespace rugosim::app {
namespace {

// `text` as one shell word: as it is when it is plain, else in single quotes.
std::string shell_word(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_not_of(
                                          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_-./:=,+@%") == std::string::npos;
  if (plain) return text;
  std::string quoted(1, '\'');
  for (const char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  quoted += '\'';
  return quoted;
}

std::string command(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& w : words) {
    if (!line.empty()) line += ' ';
    line += shell_word(w);
  }
  return line;
}

// The options that both the pass and the chunks must share (accuracy, frame rate).
std::vector<std::string> shared_options(const PlanOptions& o) {
  std::vector<std::string> words;
  if (o.accuracy.preset) words.insert(words.end(), {"--accuracy", *o.accuracy.preset});
  for (const auto& [key, value] : o.accuracy.knobs) {
    std::string flag = fmt::format("--{}", key);
    for (char& c : flag)
      if (c == '_') c = '-';
    words.insert(words.end(), {flag, fmt::format("{}", value)});
  }
  if (o.fps) words.insert(words.end(), {"--fps", fmt::format("{}", *o.fps)});
  return words;
}

}  // namespace

int run_plan_render(const PlanOptions& o) {
  std::optional<LoadedScene> loaded = load_scene_or_report(o.scene_path, o.accuracy, 1);
  if (!loaded) return kExitUsage;
  const double fps = o.fps.value_or(loaded->scene.render.fps);
  const RunFrames run =
      run_frames(loaded->scene.duration, "world.duration", fps, o.fps ? "--fps" : "render.fps",
                 loaded->world->settings().min_step);
  if (!run.error.empty()) {
    fmt::print(stderr, "error: {}\n", run.error);
    return kExitUsage;
  }
  const std::size_t frames = run.last + 1;
  if (o.chunks > frames) {
    fmt::print(stderr, "error: --chunks {}: the clip has {} frames\n", o.chunks, frames);
    return kExitUsage;
  }
  const std::string checkpoints =
      o.checkpoint_dir.empty() ? o.output + ".checkpoints" : o.checkpoint_dir;
  const std::vector<std::string> shared = shared_options(o);

  std::vector<std::string> pass = {o.program,   "simulate", o.scene_path,           "--checkpoints",
                                   checkpoints, "--every",  std::to_string(o.every)};
  pass.insert(pass.end(), shared.begin(), shared.end());
  std::vector<std::string> render = {o.program, "render", o.scene_path, "-o", o.output};
  render.insert(render.end(), shared.begin(), shared.end());
  if (!o.size.empty()) render.insert(render.end(), {"--size", o.size});
  if (o.crf) render.insert(render.end(), {"--crf", std::to_string(*o.crf)});
  render.insert(render.end(), {"--checkpoints", checkpoints});
  const std::string render_line = command(render);
  const std::string join_line =
      command({o.program, "join", o.output, "--chunks", std::to_string(o.chunks)});
  const std::string n = std::to_string(o.chunks);

  fmt::print(
      "# rugosim plan: {} -> {} in {} chunks of {} frames ({} to {} each), checkpoints "
      "every {} frames in {}\n",
      o.scene_path, o.output, o.chunks, frames, frames / o.chunks,
      (frames + o.chunks - 1) / o.chunks, o.every, checkpoints);
  fmt::print("# The folders must be shared by every task (one machine, NFS, or a volume).\n\n");
  fmt::print("# 1. The checkpoint pass (one task, first):\n{}\n\n", command(pass));
  fmt::print(
      "# 2. The chunks (any order, any machines; a complete chunk is skipped on a rerun):\n");
  for (std::size_t i = 0; i < o.chunks; ++i) {
    const auto [first, end] = chunk_frames({i, o.chunks}, frames);
    fmt::print("{} --chunk {}/{}    # frames {} to {}\n", render_line, i, o.chunks, first, end - 1);
  }
  fmt::print("\n# 3. The join (after every chunk):\n{}\n\n", join_line);

  fmt::print(
      "# GNU parallel (-N0: no argument appended, PARALLEL_SEQ numbers the jobs 1 to {}; -q: the "
      "command's words as they are):\n",
      n);
  fmt::print("{} && \\\nseq {} | parallel -j{} -N0 -q {} --chunk auto/{} && \\\n{}\n\n",
             command(pass), n, o.jobs, render_line, n, join_line);

  fmt::print("# Slurm: run this script (bash plan.sh); SLURM_ARRAY_TASK_ID picks the chunk:\n");
  fmt::print("pass=$(sbatch --parsable --wrap {})\n", shell_word(command(pass)));
  fmt::print("chunks=$(sbatch --parsable --dependency=afterok:$pass --array=0-{} --wrap {})\n",
             o.chunks - 1, shell_word(render_line + " --chunk auto/" + n));
  fmt::print("sbatch --dependency=afterok:$chunks --wrap {}\n\n", shell_word(join_line));

  fmt::print(
      "# Kubernetes: an Indexed Job (JOB_COMPLETION_INDEX picks the chunk) on a shared volume,\n"
      "# after a Job running the pass and before one running the join:\n");
  fmt::print(
      "apiVersion: batch/v1\nkind: Job\nmetadata: {{ name: rugosim-chunks }}\nspec:\n"
      "  completions: {0}\n  parallelism: {0}\n  completionMode: Indexed\n  template:\n"
      "    spec:\n      restartPolicy: OnFailure\n      containers:\n"
      "        - name: chunk\n          image: rugosim:latest   # docs/deploy/Dockerfile\n"
      "          command: [\"/bin/sh\", \"-c\", {1}]\n",
      n, nlohmann::json(render_line + " --chunk auto/" + n).dump());
  return kExitOk;
}

}  // namespace rugosim::app
