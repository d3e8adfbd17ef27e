#include "render/sinks/atomic_output_file.h"

#include <cstdint>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "render/sinks/frame_sink.h"
#include "support/file_size_limit.h"
#include "support/scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using rugosim::AtomicOutputFile;
using rugosim::SinkError;
using rugosim::write_file_atomically;
using rugosim::testing::FileSizeLimit;
using rugosim::testing::ScratchDir;

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

const AtomicOutputFile::Flush kBothFlushes[] = {AtomicOutputFile::Flush::kToDisk,
                                                AtomicOutputFile::Flush::kRenameOnly};

TEST(AtomicOutputFile, TheTargetAppearsWholeOnlyAtCommit) {
  for (const AtomicOutputFile::Flush flush : kBothFlushes) {
    const ScratchDir directory("atomic_output_test");
    const fs::path path = directory.path() / "table.csv";
    { std::ofstream(path) << "old\n"; }
    AtomicOutputFile file(path.string(), flush);
    file.write(std::string_view("a,b\n"));
    file.write(std::string_view("1,2\n"));
    // Before commit the target is as it was, beside one temporary file.
    EXPECT_EQ(contents(path), "old\n");
    const std::vector<std::string> during = directory.listing();
    ASSERT_EQ(during.size(), 2u);
    EXPECT_EQ(during[1].rfind("table.csv.tmp-", 0), 0u) << during[1];
    file.commit();
    file.commit();  // a second commit does nothing
    EXPECT_EQ(contents(path), "a,b\n1,2\n");
    EXPECT_EQ(directory.listing(), std::vector<std::string>{"table.csv"});
    EXPECT_THROW(file.write(std::string_view("late")), SinkError);
  }
}

TEST(AtomicOutputFile, AnAbandonedWriterLeavesTheTargetAsItWas) {
  const ScratchDir directory("atomic_output_test");
  const fs::path kept = directory.path() / "stats.json";
  { std::ofstream(kept) << "{}\n"; }
  {
    AtomicOutputFile file(kept.string());
    file.write(std::string_view("{\"partial\": "));
  }  // destroyed without commit: an error or an interruption
  EXPECT_EQ(contents(kept), "{}\n");
  // A new file abandoned leaves nothing at all.
  {
    AtomicOutputFile file((directory.path() / "new.csv").string());
    file.write(std::string_view("x"));
  }
  EXPECT_EQ(directory.listing(), std::vector<std::string>{"stats.json"});
}

TEST(AtomicOutputFile, ALinkKeepsPointingAtTheReplacedFile) {
  const ScratchDir directory("atomic_output_test");
  const fs::path real = directory.path() / "run_42.csv";
  const fs::path link = directory.path() / "latest.csv";
  { std::ofstream(real) << "old\n"; }
  fs::create_symlink("run_42.csv", link);
  write_file_atomically(link.string(), std::vector<std::uint8_t>{'n', 'e', 'w', '\n'});
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(contents(real), "new\n");
  EXPECT_EQ(directory.listing(), (std::vector<std::string>{"latest.csv", "run_42.csv"}));
}

TEST(AtomicOutputFile, DevicesAndPipesAreWrittenDirectly) {
  // /dev/null exists and is not a regular file: no temporary file beside it, no rename.
  write_file_atomically("/dev/null", std::vector<std::uint8_t>(1000, 7));
  const ScratchDir directory("atomic_output_test");
  const fs::path fifo = directory.path() / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A reader on the other end (opened non-blocking first, so that the writer's open returns).
  const int read_end = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(read_end, 0);
  write_file_atomically(fifo.string(), std::vector<std::uint8_t>{'o', 'k'});
  char got[3] = {};
  EXPECT_EQ(::read(read_end, got, 2), 2);
  ::close(read_end);
  EXPECT_EQ(std::string(got), "ok");
  EXPECT_EQ(directory.listing(), std::vector<std::string>{"pipe"});
}

TEST(AtomicOutputFile, FailuresNameThePathAndLeaveNothingBehind) {
  const ScratchDir directory("atomic_output_test");
  const fs::path path = directory.path() / "big.bin";
  { std::ofstream(path) << "old\n"; }
  std::mt19937 rng(7);
  std::vector<std::uint8_t> big(100000);
  for (std::uint8_t& b : big)
    b = static_cast<std::uint8_t>(rng());
  for (const AtomicOutputFile::Flush flush : kBothFlushes) {
    std::string message;
    {
      const FileSizeLimit limit(1000);  // write(2) fails with EFBIG part way
      try {
        write_file_atomically(path.string(), big, flush);
      } catch (const SinkError& error) {
        message = error.what();
      }
    }
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("File too large"), std::string::npos) << message;
    EXPECT_EQ(contents(path), "old\n");
    EXPECT_EQ(directory.listing(), std::vector<std::string>{"big.bin"});
  }
  if (fs::exists("/dev/full")) {
    try {
      write_file_atomically("/dev/full", big);
      ADD_FAILURE() << "writing to /dev/full succeeded";
    } catch (const SinkError& error) {
      EXPECT_NE(std::string(error.what()).find("/dev/full: cannot write: No space left on device"),
                std::string::npos)
          << error.what();
    }
  }
  const std::string nowhere = (directory.path() / "missing" / "out.csv").string();
  try {
    AtomicOutputFile file(nowhere);
    ADD_FAILURE() << "created a file in a missing folder";
  } catch (const SinkError& error) {
    EXPECT_EQ(std::string(error.what()), nowhere + ": cannot create: No such file or directory");
  }
}

}  // namespace
