// A flow_item_per_poi that never ends, for the hang tests (tests/opencl/test_opencl_hang.cpp):
// the arguments of kernels/opencl/opencl.cl's, and a loop whose condition, width > 0, holds for
// every real problem but is unknown to the compiler; the atomic increment in it is a side effect,
// so the loop can be neither proven finite nor deleted.
kernel void flow_item_per_poi(global const uchar* frames, global uint* records, int width,
                              int height, int search_radius, uint feature_threshold,
                              uint sad_threshold, int4 grid_x, int4 grid_y, uint total_pois) {
  const size_t i = get_global_id(0);
  if (i >= total_pois) return;
  while (width > 0) atomic_inc(&records[8 * i]);
}
