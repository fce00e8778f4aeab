#include "PngDecoder.h"

#include <opencv2/imgproc.hpp>

#include <png.h>

#include <cstring>

namespace omnirange
{
namespace
{
struct Source
{
	const unsigned char* at;
	std::size_t left;
	std::string message;
};

[[noreturn]] void fail(png_structp png, png_const_charp message)
{
	static_cast<Source*>(png_get_error_ptr(png))->message = message;
	png_longjmp(png, 1);
}

/** libpng's warnings (an sRGB profile it knows to be wrong, a text chunk it
 * skips) leave the pixels whole; damage to the pixels is an error. */
void ignoreWarning(png_structp, png_const_charp) {}

void readBytes(png_structp png, png_bytep out, png_size_t n)
{
	auto* s = static_cast<Source*>(png_get_io_ptr(png));
	if (n > s->left) png_error(png, "truncated: the file ends inside a chunk");
	std::memcpy(out, s->at, n);
	s->at += n, s->left -= n;
}

/** The transformations OpenCV's PNG decoder asks for in colour: 8 bits per
 * channel, palette and grey expanded, alpha dropped, blue first. */
void askForBgr(png_structp png, png_infop info)
{
	const int type = png_get_color_type(png, info);
	if (png_get_bit_depth(png, info) == 16) png_set_strip_16(png);
	if (type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
	if ((type & PNG_COLOR_MASK_COLOR) == 0) png_set_gray_to_rgb(png);
	if (png_get_bit_depth(png, info) < 8) png_set_expand_gray_1_2_4_to_8(png);
	png_set_strip_alpha(png);
	png_set_bgr(png);
}
}  // namespace

std::string decodePng(const unsigned char* bytes, std::size_t size, bool grey, cv::Mat& image)
{
	Source source{bytes, size, ""};
	png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &source, fail, ignoreWarning);
	png_infop info = png ? png_create_info_struct(png) : nullptr;
	if (!info)
	{
		png_destroy_read_struct(&png, nullptr, nullptr);
		return "libpng could not start";
	}
	image.release();
	// Only `image`, the caller's, changes between setjmp and a longjmp.
	if (setjmp(png_jmpbuf(png)))
	{
		png_destroy_read_struct(&png, &info, nullptr);
		image.release();
		return source.message;
	}
	png_set_read_fn(png, &source, readBytes);
	png_read_info(png, info);
	askForBgr(png, info);
	const int passes = png_set_interlace_handling(png);  // 1, or 7 for an interlaced PNG
	png_read_update_info(png, info);
	image.create(static_cast<int>(png_get_image_height(png, info)), static_cast<int>(png_get_image_width(png, info)),
				 CV_8UC3);
	// Row by row into the caller's image: no object of ours lives between here and a
	// longjmp, which would skip its destructor (a vector of row pointers leaked so).
	for (int pass = 0; pass < passes; ++pass)
		for (int r = 0; r < image.rows; ++r) png_read_row(png, image.ptr(r), nullptr);
	png_read_end(png, nullptr);
	png_destroy_read_struct(&png, &info, nullptr);
	if (grey) cv::cvtColor(image, image, cv::COLOR_BGR2GRAY);
	return "";
}
}  // namespace omnirange
