#pragma once
// Decoding the image of a CObservationImage, stored inside the rawlog or
// externally in NAME_Images/, with errors that name the file.

#include <omnirange/core/CameraModel.h>

#include <mrpt/obs/CObservationImage.h>
#include <opencv2/core.hpp>

namespace omnirange
{
/** An image file (of the sensor `label`) as 8-bit BGR; empty if it does not
 * decode. Throws std::runtime_error naming the file if it cannot be read or
 * is a cut JPEG or PNG (which would decode with grey rows and only a warning). */
cv::Mat decodeImageFile(const std::string& file, const std::string& label);

/** The observation's image as 8-bit BGR. Throws std::runtime_error naming
 * the file if an external image is missing or unreadable. Thread-safe. */
cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs);

/** The same, and throws std::runtime_error naming the image unless it has
 * the camera's size. */
cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs, const CameraParams& camera);

}  // namespace omnirange
