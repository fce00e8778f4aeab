#pragma once
// Decoding the image of a CObservationImage, stored inside the rawlog or
// externally in NAME_Images/, with errors that name the file.

#include <omnirange/core/CameraModel.h>
#include <omnirange/core/PixelClassifier.h>

#include <mrpt/obs/CObservationImage.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

namespace omnirange
{
/** Whether `file` is named as an image the programs read from a folder
 * (.jpg, .jpeg, .png, .pgm, .ppm, .bmp, in any case). */
bool isImageFileName(const std::string& file);


/** An image file (of the sensor `label`; "" for none) as OpenCV's imdecode
 * `flags` make it (8-bit BGR by default). Throws std::runtime_error naming
 * the file if it is not a regular file, cannot be read, is empty, is a cut
 * JPEG or PNG, a JPEG whose coded data libjpeg finds damaged (both would
 * decode with grey blocks and only a warning; a camera's trailer after the
 * end marker is fine), does not decode, or its header says it has more than
 * kMaxImagePixels. A JPEG with a `region` is decoded only around it (the
 * rest black), its pixels there those of the whole decode; other formats
 * and an empty region, whole. */
cv::Mat decodeImageFile(const std::string& file, const std::string& label, int flags = cv::IMREAD_COLOR,
						const PixelBox& region = {});
/** The same into `image`, a JPEG's buffer reused when it has the size
 * already (outside `region`, what it held: black when new). */
void decodeImageFile(const std::string& file, const std::string& label, int flags, const PixelBox& region,
					 cv::Mat& image);

/** The observation's image as 8-bit BGR; an external JPEG only around
 * `region` (decodeImageFile). Throws std::runtime_error naming the file if
 * an external image is missing or unreadable. Thread-safe. */
cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs, const PixelBox& region = {});

/** The same, and throws std::runtime_error naming the image unless it has
 * the camera's size. */
cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs, const CameraParams& camera, const PixelBox& region = {});
/** The same into `image` (decodeImageFile): a log's scan decodes into a few buffers, not a new one per image. */
void decodeImage(const mrpt::obs::CObservationImage& obs, const CameraParams& camera, const PixelBox& region,
				 cv::Mat& image);

/** Throws std::runtime_error naming the image `obs` unless `img` has the camera's size. */
void requireCameraSize(const cv::Mat& img, const mrpt::obs::CObservationImage& obs, const CameraParams& camera);

/** "WIDTHxHEIGHT", as messages give an image's size. */
std::string sizeText(const cv::Size& size);

}  // namespace omnirange
