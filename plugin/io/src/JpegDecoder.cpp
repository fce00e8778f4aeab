#include "JpegDecoder.h"

#include <csetjmp>
#include <cstdio>

#include <jpeglib.h>
#include <jerror.h>

namespace omnirange
{
namespace
{
struct Failure
{
	jpeg_error_mgr manager;
	std::jmp_buf jump;
	char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void fail(j_common_ptr info)
{
	auto* f = reinterpret_cast<Failure*>(info->err);
	(*info->err->format_message)(info, f->message);
	std::longjmp(f->jump, 1);
}

/** libjpeg's warnings (level -1) that mean the coded data is damaged; the
 * others (an Adobe or JFIF version, a bogus ICC profile) leave the pixels whole.
 * Padding before the end-of-image marker, common from webcams, is allowed. */
void onMessage(j_common_ptr info, int level)
{
	if (level >= 0) return;  // trace messages
	const int code = info->err->msg_code;
	const bool padding_at_end = code == JWRN_EXTRANEOUS_DATA && info->err->msg_parm.i[1] == JPEG_EOI;
	const bool damaged = code == JWRN_HIT_MARKER || code == JWRN_JPEG_EOF || code == JWRN_MUST_RESYNC ||
						 code == JWRN_HUFF_BAD_CODE || code == JWRN_ARITH_BAD_CODE || code == JWRN_BOGUS_PROGRESSION ||
						 code == JWRN_NOT_SEQUENTIAL || (code == JWRN_EXTRANEOUS_DATA && !padding_at_end);
	if (damaged) fail(info);
}

}  // namespace

std::string decodeJpeg(const unsigned char* bytes, std::size_t size, bool grey, cv::Mat& image)
{
	jpeg_decompress_struct info;
	Failure failure;
	info.err = jpeg_std_error(&failure.manager);
	failure.manager.error_exit = fail;
	failure.manager.emit_message = onMessage;
	image.release();
	// Only `image`, the caller's, changes between setjmp and a longjmp (a local would be indeterminate after it).
	if (setjmp(failure.jump))
	{
		jpeg_destroy_decompress(&info);
		image.release();
		return failure.message;
	}
	jpeg_create_decompress(&info);
	jpeg_mem_src(&info, bytes, static_cast<unsigned long>(size));
	jpeg_read_header(&info, TRUE);
	const bool cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
	info.out_color_space = cmyk ? JCS_CMYK : grey ? JCS_GRAYSCALE : JCS_EXT_BGR;
	jpeg_start_decompress(&info);
	image.create(static_cast<int>(info.output_height), static_cast<int>(info.output_width),
				 CV_8UC(info.output_components));
	while (info.output_scanline < info.output_height)
	{
		JSAMPROW row = image.ptr(static_cast<int>(info.output_scanline));
		jpeg_read_scanlines(&info, &row, 1);
	}
	// An Exif orientation is not applied: cx, cy and the azimuth are in the sensor's own pixel frame, and one
	// image of a log tagged otherwise (edited, saved by another tool) would be scanned turned or mirrored.
	const bool opencv_decodes = cmyk;
	jpeg_finish_decompress(&info);
	jpeg_destroy_decompress(&info);
	if (opencv_decodes) image.release();
	return "";
}
}  // namespace omnirange
