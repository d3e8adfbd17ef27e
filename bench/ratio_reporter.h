// Benchmarks report ratios against a baseline measured in the same run, because a shared
// machine's absolute timings drift from run to run while ratios hold.
//
// Naming rule: a benchmark named "<family>/<variant>/<args...>" is compared with the run named
// "<family>/baseline/<args...>" (same family and arguments), or with the variant a program named
// as its family's baseline (set_baseline_variant). The console output of Google Benchmark is
// kept; a Markdown table of ratios follows it.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

namespace rugosim::bench {

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  // With a path, Finalize also writes the runs as a tab-separated table there.
  explicit RatioReporter(std::string table_path = {}) : table_path_(std::move(table_path)) {}
  void ReportRuns(const std::vector<Run>& runs) override;
  void Finalize() override;

 private:
  struct Entry {
    std::string family, variant, args;
    double ns_per_iteration = 0.0;
    bool median = false;  // the median over repetitions, not a single run
  };
  std::vector<Entry> entries_;
  std::string table_path_;
};

// Makes `variant` the baseline of `family` instead of "baseline" (e.g. a competitor's run that
// the issue names). Call before run_with_ratios.
void set_baseline_variant(const std::string& family, const std::string& variant);

// Runs every registered benchmark with the ratio table: use as the body of main(). A
// --ratio_table=FILE argument also writes the runs as a tab-separated table (for plots).
// Repetitions are interleaved at random by default (--benchmark_enable_random_interleaving=
// false turns it off): a baseline and its variants then sample the machine's drift alike,
// where run one after the other the later ones met another load (ratios of medians moved by
// 10-30% between runs on these machines, within 7% interleaved).
int run_with_ratios(int argc, char** argv);

}  // namespace rugosim::bench
