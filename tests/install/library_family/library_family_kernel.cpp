// The library of tests/install/library_family: configured by the install test, never built.
int library_family_kernel() { return 0; }
