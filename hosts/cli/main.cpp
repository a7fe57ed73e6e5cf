#include "device_wait.hpp"
#include "pxflow_app.hpp"

int main(int argc, char** argv) {
  const int code = pxflow::run_pxflow(argc, argv);
  // A device given up on may still spin in its driver's threads: end without joining them.
  pxflow::exit_now_if_device_abandoned(code);
  return code;
}
