// Sets an environment variable for one scope, restoring what was there before (the tests of the
// variables pxflow reads, and of a driver's, e.g. Mesa's MESA_SHADER_CACHE_DISABLE).
#pragma once
#include <cstdlib>
#include <optional>
#include <string>

namespace pxflow::test {

class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

}  // namespace pxflow::test
