#include "ratio_reporter.h"

#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace rugosim::bench {

namespace {

std::map<std::string, std::string>& baseline_variants() {
  static std::map<std::string, std::string> variants;
  return variants;
}

std::string baseline_variant(const std::string& family) {
  const auto it = baseline_variants().find(family);
  return it == baseline_variants().end() ? "baseline" : it->second;
}

// Splits "family/variant/args" at the first two slashes.
bool split_name(const std::string& name, std::string& family, std::string& variant,
                std::string& args) {
  const auto first = name.find('/');
  if (first == std::string::npos) return false;
  const auto second = name.find('/', first + 1);
  family = name.substr(0, first);
  variant =
      name.substr(first + 1, second == std::string::npos ? std::string::npos : second - first - 1);
  args = second == std::string::npos ? "" : name.substr(second + 1);
  return true;
}
}  // namespace

void RatioReporter::ReportRuns(const std::vector<Run>& runs) {
  for (const Run& run : runs) {
    if (run.error_occurred) continue;
    const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
    if (!median && run.run_type != Run::RT_Iteration) continue;
    Entry e;
    if (!split_name(run.run_name.str(), e.family, e.variant, e.args)) continue;
    e.ns_per_iteration = run.GetAdjustedRealTime() *
                         benchmark::GetTimeUnitMultiplier(benchmark::kNanosecond) /
                         benchmark::GetTimeUnitMultiplier(run.time_unit);
    e.median = median;
    entries_.push_back(e);
  }
  ConsoleReporter::ReportRuns(runs);
}

void RatioReporter::Finalize() {
  ConsoleReporter::Finalize();
  // With repetitions, the median stands for the benchmark and its single runs are dropped.
  std::set<std::string> with_median;
  for (const Entry& e : entries_) {
    if (e.median) with_median.insert(e.family + "/" + e.variant + "/" + e.args);
  }
  std::erase_if(entries_, [&](const Entry& e) {
    return !e.median && with_median.count(e.family + "/" + e.variant + "/" + e.args) > 0;
  });
  std::map<std::string, double> baseline;  // family + args -> ns
  for (const Entry& e : entries_) {
    if (e.variant == baseline_variant(e.family)) {
      baseline[e.family + "/" + e.args] = e.ns_per_iteration;
    }
  }
  std::printf("\n| benchmark | args | time / baseline |\n|---|---|---|\n");
  for (const Entry& e : entries_) {
    if (e.variant == baseline_variant(e.family)) continue;
    const auto it = baseline.find(e.family + "/" + e.args);
    if (it == baseline.end() || it->second <= 0.0) {
      std::printf("| %s/%s | %s | (no baseline) |\n", e.family.c_str(), e.variant.c_str(),
                  e.args.c_str());
    } else {
      std::printf("| %s/%s | %s | %.3f |\n", e.family.c_str(), e.variant.c_str(), e.args.c_str(),
                  e.ns_per_iteration / it->second);
    }
  }
  std::fflush(stdout);
  if (!table_path_.empty()) {
    // Tab-separated, for plots: family, variant, args, ns per iteration (the median where
    // there were repetitions).
    if (std::FILE* table = std::fopen(table_path_.c_str(), "w")) {
      std::fprintf(table, "family\tvariant\targs\tns\n");
      for (const Entry& e : entries_) {
        std::fprintf(table, "%s\t%s\t%s\t%.9g\n", e.family.c_str(), e.variant.c_str(),
                     e.args.c_str(), e.ns_per_iteration);
      }
      std::fclose(table);
    } else {
      std::fprintf(stderr, "cannot write %s\n", table_path_.c_str());
    }
  }
}

void set_baseline_variant(const std::string& family, const std::string& variant) {
  baseline_variants()[family] = variant;
}

int run_with_ratios(int argc, char** argv) {
  // --ratio_table=FILE (ours, taken out before Google Benchmark parses the rest).
  // Random interleaving goes first, so that the command line's own setting, parsed later, wins.
  std::string table;
  static char interleave[] = "--benchmark_enable_random_interleaving=true";
  std::vector<char*> args{argv[0], interleave};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--ratio_table=", 0) == 0) {
      table = arg.substr(std::string("--ratio_table=").size());
    } else {
      args.push_back(argv[i]);
    }
  }
  int count = static_cast<int>(args.size());
  args.push_back(nullptr);
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
  RatioReporter reporter(table);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}

}  // namespace rugosim::bench
