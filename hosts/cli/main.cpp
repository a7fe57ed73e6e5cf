#include "pxflow_app.hpp"

int main(int argc, char** argv) { return pxflow::run_pxflow(argc, argv); }
