// Runs one of the test programs (built by CMake into build_paths::gap8_program_dir) on a fresh
// cluster, capturing what it prints.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "gap8/cluster.h"
#include "gap8/elf_loader.h"

struct ProgramRun {
  std::unique_ptr<gap8::Cluster> cluster;
  gap8::ElfImage image;
  gap8::RunResult result;
  std::string output;
  bool ok() const { return !result.fault && result.exit_code == 0; }
  std::string Describe() const;  // for test failure messages
};

std::string ProgramPath(const std::string& name);

struct RunOptions {
  int cores = 8;
  bool contention = true;
  uint64_t max_cycles = 200'000'000;
  std::function<void(gap8::Cluster&, const gap8::ElfImage&)> before_run;
};

inline RunOptions OnCores(int cores) {
  RunOptions options;
  options.cores = cores;
  return options;
}

ProgramRun RunProgram(const std::string& name, const RunOptions& options);
