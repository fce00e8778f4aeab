#include "JpegDecoder.h"

#include <algorithm>
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

/** [px] decoded around a region: a pixel's colour takes its chroma from the
 * samples beside it (fancy upsampling), and the decoder treats the edge of a
 * crop as the image's; an iMCU (16 px at 4:2:0) keeps the region's pixels
 * away from that edge. */
constexpr int kRegionMargin = 16;

/** The rows and columns of `region` (and the margin) into `image`, the rest left as it is. */
void readRegion(jpeg_decompress_struct& info, const PixelBox& region, cv::Mat& image)
{
	const int w = image.cols, h = image.rows;
	JDIMENSION x = static_cast<JDIMENSION>(std::max(0, region.left - kRegionMargin));
	JDIMENSION width = static_cast<JDIMENSION>(std::min(w, region.right + 1 + kRegionMargin)) - x;
	jpeg_crop_scanline(&info, &x, &width);  // widened to whole iMCUs
	const auto top = static_cast<JDIMENSION>(std::max(0, region.top - kRegionMargin));
	const auto bottom = static_cast<JDIMENSION>(std::min(h, region.bottom + 1 + kRegionMargin));
	jpeg_skip_scanlines(&info, top);
	while (info.output_scanline < bottom)
	{
		JSAMPROW row = image.ptr(static_cast<int>(info.output_scanline)) + x * image.elemSize();
		jpeg_read_scanlines(&info, &row, 1);
	}
	// To the end: libjpeg-turbo stops there, unread. Damage in the rows above and in the box is found (their
	// coded data is read in order); below the box, where the scan reads nothing, it is not looked for.
	jpeg_skip_scanlines(&info, info.output_height - info.output_scanline);
}

}  // namespace

std::string decodeJpeg(const unsigned char* bytes, std::size_t size, bool grey, cv::Mat& image, const PixelBox& region)
{
	jpeg_decompress_struct info;
	Failure failure;
	info.err = jpeg_std_error(&failure.manager);
	failure.manager.error_exit = fail;
	failure.manager.emit_message = onMessage;
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
	const uchar* before = image.data;
	image.create(static_cast<int>(info.output_height), static_cast<int>(info.output_width),
				 CV_8UC(info.output_components));
	if (!region.empty() && region.right < image.cols && region.bottom < image.rows)  // else the size check refuses it
	{
		if (image.data != before) image = cv::Scalar::all(0);  // a new buffer: black; a reused one keeps what it had
		readRegion(info, region, image);
	}
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
