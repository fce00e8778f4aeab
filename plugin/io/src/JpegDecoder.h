#pragma once
// A JPEG decoded with libjpeg directly, so that its warnings are heard: a
// JPEG whose coded data is cut or damaged in the middle still ends with its
// end-of-image marker, and libjpeg then fills the rest with grey and only
// prints "Corrupt JPEG data" on stderr, which OpenCV's imdecode lets pass.

#include <omnirange/core/PixelClassifier.h>

#include <opencv2/core.hpp>

#include <string>

namespace omnirange
{
/** Decodes the JPEG `bytes` into 8-bit BGR, or grey if `grey`. Returns why
 * its data is damaged ("Corrupt JPEG data: premature end of data segment"),
 * or "" with `image` set; leaves `image` empty where OpenCV must decode it
 * (CMYK) after this check passed. An Exif orientation is not applied.
 * `image` is decoded into, its buffer reused when it has the size and type
 * already (the caller's alone: a shared one would change under its other
 * holders). With a `region`, only the rows and columns around it are
 * dequantised, transformed and colour-converted (the rest of a new buffer
 * black, of a reused one as it was): its
 * pixels are those of the whole image's decode. The whole of the coded
 * data is still read, so damage anywhere is found as without one. */
std::string decodeJpeg(const unsigned char* bytes, std::size_t size, bool grey, cv::Mat& image,
					   const PixelBox& region = {});
}  // namespace omnirange
