#pragma once
// Images written as files of their own (figures, true maps, tuner pictures):
// encoded as the path's extension names, then written or staged as any
// other output (config/AtomicWrite.h).

#include <omnirange/config/Output.h>

#include <opencv2/core.hpp>

#include <string>

namespace omnirange
{
/** `image` encoded as its path's extension names (.png, .jpg); throws
 * std::runtime_error naming the path when it cannot be. */
std::string encodedImage(const std::string& path, const cv::Mat& image);
/** Encodes `image` as its path's extension names and writes it atomically. */
void writeImageAtomically(const std::string& path, const cv::Mat& image);
/** `image` encoded as its path's extension names, staged in `set`. */
void stageImage(OutputSet& set, const std::string& path, const cv::Mat& image);
}  // namespace omnirange
