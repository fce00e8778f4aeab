#pragma once
// A PNG decoded with libpng directly, so that a damaged file gives one reason
// and no lines of libpng's own: through OpenCV's imdecode, libpng prints
// "libpng error: ..." and "libpng warning: ..." on stderr before the
// program's own one-line error, and warns about harmless colour profiles.

#include <opencv2/core.hpp>

#include <string>

namespace omnirange
{
/** Decodes the PNG `bytes` into 8-bit BGR, or grey if `grey`, as OpenCV's
 * imdecode does (no gamma correction; 16-bit cut to its high byte; alpha and
 * transparency dropped). Returns why the file is damaged ("IDAT: CRC error"),
 * or "" with `image` set. */
std::string decodePng(const unsigned char* bytes, std::size_t size, bool grey, cv::Mat& image);
}  // namespace omnirange
