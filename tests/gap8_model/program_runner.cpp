#include "program_runner.h"

#include "build_paths.hpp"

std::string ProgramPath(const std::string& name) {
  return std::string(build_paths::gap8_program_dir) + "/" + name + ".elf";
}

std::string ProgramRun::Describe() const {
  std::string s = "output: " + output;
  if (result.fault) s += "\nfault: " + result.fault->Message();
  s += "\nexit code " + std::to_string(result.exit_code) + ", " + std::to_string(result.cycles) +
       " cycles";
  return s;
}

ProgramRun RunProgram(const std::string& name, const RunOptions& options) {
  ProgramRun run;
  gap8::ClusterConfig config;
  config.cores = options.cores;
  config.contention = options.contention;
  config.max_cycles = options.max_cycles;
  auto sink = std::make_shared<std::string>();
  config.putc = [sink](char c) { *sink += c; };
  run.cluster = std::make_unique<gap8::Cluster>(config);
  run.image = gap8::LoadElf(ProgramPath(name), run.cluster->memory());
  run.cluster->Start(run.image.entry);
  if (options.before_run) options.before_run(*run.cluster, run.image);
  run.result = run.cluster->Run();
  run.output = *sink;
  return run;
}
