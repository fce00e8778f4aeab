#pragma once
// The report's figures drawn with OpenCV: the accuracy histogram (paper
// Fig. 9) and maps side by side.

#include <opencv2/core.hpp>

#include <string>
#include <utility>
#include <vector>

namespace omnirange::eval
{
/** A bar chart of the differences like paper Fig. 9 (bins of `bin` m over
 * [-range, range]), as an 8-bit BGR image. */
cv::Mat differenceHistogram(const std::vector<double>& d, const std::string& title, double range, double bin = 0.05);

/** Images side by side, each with its title above; all must have the same height. */
cv::Mat sideBySide(const std::vector<std::pair<std::string, cv::Mat>>& images);

}  // namespace omnirange::eval
