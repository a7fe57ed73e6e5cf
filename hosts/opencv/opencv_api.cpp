// The module's one exported function: the table of what it does (opencv_api.hpp).
#include "opencv_api.hpp"

#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/logger.hpp>

#include "opencv_mat.hpp"

namespace pxflow::opencv {
namespace {

void quiet() { cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT); }

void set_threads(int threads) { cv::setNumThreads(threads); }

const Api kApi = {
    .version = kApiVersion,
    .quiet = quiet,
    .set_threads = set_threads,
    .decode_gray = decode_gray,
    .draw_flow_png = draw_flow_png,
    .open_video = open_video,
    .read_video_frame = read_video_frame,
    .close_video = close_video,
    .warp_affine = warp_affine,
    .gaussian_blur = gaussian_blur,
    .gain_offset = gain_offset,
    .add_noise = add_noise,
    .lucas_kanade = lucas_kanade,
    .create_dis = create_dis,
    .dis_mean_flow = dis_mean_flow,
    .destroy_dis = destroy_dis,
};

}  // namespace
}  // namespace pxflow::opencv

extern "C" __attribute__((visibility("default"))) const pxflow::opencv::Api* pxflow_opencv_api() {
  return &pxflow::opencv::kApi;
}
