#pragma once
// Decoding the image of a CObservationImage, stored inside the rawlog or
// externally in NAME_Images/, with errors that name the file.

#include <omnirange/core/CameraModel.h>

#include <mrpt/obs/CObservationImage.h>
#include <opencv2/core.hpp>

namespace omnirange
{
/** The observation's image as 8-bit BGR. Throws std::runtime_error naming
 * the file if an external image is missing or unreadable. Thread-safe. */
cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs);

/** The same, and throws std::runtime_error naming the image unless it has
 * the camera's size. */
cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs, const CameraParams& camera);

}  // namespace omnirange
