// What readers refuse before they read: a FIFO or a device (it would block
// or never end), an image whose header asks for too many pixels, a JPEG cut
// short (judged by its markers, so a camera's trailer is fine), a time that
// is not decimal seconds within MRPT's clock.
#include <omnirange/core/ColourModel.h>
#include <omnirange/io/ObservationImage.h>
#include <omnirange/config/OptionsTable.h>
#include <omnirange/core/Rangefinder.h>

#include "../common/FactorySample.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

using namespace omnirange;
namespace fs = std::filesystem;

namespace
{
std::string dir(const std::string& name) { return test::freshDir("omnirange_bad_files", name); }

using test::errorOf;

std::string jpeg()
{
	cv::Mat img(48, 64, CV_8UC3, cv::Scalar(40, 120, 200));
	cv::circle(img, {32, 24}, 10, cv::Scalar(0, 0, 0), -1);
	std::vector<uchar> buf;
	cv::imencode(".jpg", img, buf);
	return std::string(buf.begin(), buf.end());
}
}  // namespace

TEST(BadFiles, AFifoIsRefusedByEveryReaderWithoutBlocking)
{
	const std::string d = dir("fifo");
	const std::string fifo = d + "/pipe";
	ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
	EXPECT_NE(errorOf([&] { forEachDataLine(fifo, "laser log", [](int, const std::string&) {}); }).find("not a regular file"),
			  std::string::npos);
	EXPECT_NE(errorOf([&] { RangefinderParams::loadFromFile(fifo, "rangefinder"); }), "");
	EXPECT_NE(errorOf([&] { ColourModel::load(fifo); }), "");
	EXPECT_NE(errorOf([&] { decodeImageFile(fifo, "OMNICAM"); }).find("not a regular file"), std::string::npos);
	EXPECT_NE(errorOf([&] { requireNoRepeatedKeys(fifo); }).find("not a regular file"), std::string::npos);
	// A chain of more links than the system follows is not "no file", and not an ini that is missing.
	std::ofstream(d + "/link0") << "[rangefinder]\nh = 1\n";
	for (int i = 1; i <= 41; ++i) fs::create_symlink(d + "/link" + std::to_string(i - 1), d + "/link" + std::to_string(i));
	const std::string last = d + "/link41";
	EXPECT_NE(errorOf([&] { decodeImageFile(last, "OMNICAM"); }).find("more than 40 in a row"), std::string::npos);
	EXPECT_NE(errorOf([&] { requireNoRepeatedKeys(last); }).find("Too many levels of symbolic links"), std::string::npos)
		<< errorOf([&] { requireNoRepeatedKeys(last); });
}

TEST(BadFiles, AJpegIsJudgedByItsMarkersSoATrailerIsFineAndACutIsNot)
{
	const std::string d = dir("jpeg");
	const std::string whole = jpeg();
	std::ofstream(d + "/trailer.jpg", std::ios::binary) << whole << std::string("CAMERA-TRAILER\xff\x00 and more", 24);
	const cv::Mat m = decodeImageFile(d + "/trailer.jpg", "OMNICAM");
	EXPECT_EQ(m.cols, 64);
	EXPECT_EQ(m.rows, 48);
	std::ofstream(d + "/cut.jpg", std::ios::binary) << whole.substr(0, whole.size() * 2 / 3);
	EXPECT_NE(errorOf([&] { decodeImageFile(d + "/cut.jpg", "OMNICAM"); }).find("truncated"), std::string::npos);
	// A cut inside the headers, before the scan.
	std::ofstream(d + "/head.jpg", std::ios::binary) << whole.substr(0, 30);
	EXPECT_NE(errorOf([&] { decodeImageFile(d + "/head.jpg", "OMNICAM"); }), "");
}

TEST(BadFiles, AJpegDamagedInsideIsRefusedThoughItsEndMarkerIsThere)
{
	const std::string d = dir("jpeg_inside");
	cv::Mat img(240, 320, CV_8UC3);
	cv::randu(img, 0, 255);  // texture: coded data much longer than the headers
	std::vector<uchar> buf;
	cv::imencode(".jpg", img, buf);
	const std::string whole(buf.begin(), buf.end());
	const std::size_t n = whole.size();
	// Its middle third cut out: libjpeg meets the end marker early, fills grey and only warns.
	std::ofstream(d + "/midcut.jpg", std::ios::binary) << whole.substr(0, n / 3) + whole.substr(2 * n / 3);
	for (const int flags : {cv::IMREAD_COLOR, cv::IMREAD_GRAYSCALE})
	{
		const std::string why = errorOf([&] { decodeImageFile(d + "/midcut.jpg", "OMNICAM", flags); });
		EXPECT_NE(why.find("midcut.jpg' of OMNICAM is damaged: Corrupt JPEG data"), std::string::npos) << why;
	}
	// Padding before the end marker, as webcams write, leaves the pixels whole.
	std::ofstream(d + "/padded.jpg", std::ios::binary) << whole.substr(0, n - 2) + std::string("\0\0\0", 3) + whole.substr(n - 2);
	const cv::Mat padded = decodeImageFile(d + "/padded.jpg", "OMNICAM");
	const cv::Mat reference = cv::imdecode(buf, cv::IMREAD_COLOR);
	ASSERT_EQ(padded.size(), reference.size());
	EXPECT_EQ(cv::norm(padded, reference, cv::NORM_INF), 0.0) << "decoded unlike OpenCV";
	const cv::Mat grey = decodeImageFile(d + "/padded.jpg", "OMNICAM", cv::IMREAD_GRAYSCALE);
	EXPECT_EQ(cv::norm(grey, cv::imdecode(buf, cv::IMREAD_GRAYSCALE), cv::NORM_INF), 0.0);
}

TEST(BadFiles, AJpegsExifOrientationIsNotAppliedTheSensorsPixelsAreReadAsWritten)
{
	// One frame of a log re-saved by a tool that tags it: scanned turned, its ranges would be another bearing's.
	const std::string d = dir("jpeg_exif"), plain = jpeg();
	std::ofstream(d + "/plain.jpg", std::ios::binary) << plain;
	const cv::Mat reference = decodeImageFile(d + "/plain.jpg", "OMNICAM");
	for (const char orientation : {2, 3, 6, 8})
	{
		// APP1: "Exif", a little-endian TIFF header and one IFD entry, Orientation (0x0112), a SHORT.
		const std::string exif = std::string("Exif\0\0II*\0\x08\0\0\0\x01\0\x12\x01\x03\0\x01\0\0\0", 24) +
								 orientation + std::string(7, '\0');
		const std::size_t length = exif.size() + 2;
		const std::string tagged = plain.substr(0, 2) + "\xff\xe1" + static_cast<char>(length >> 8) +
								   static_cast<char>(length & 0xff) + exif + plain.substr(2);
		const std::string file = d + "/tagged" + std::to_string(orientation) + ".jpg";
		std::ofstream(file, std::ios::binary) << tagged;
		if (orientation == 3)
		{
			// OpenCV itself turns it: the tag is read.
			const cv::Mat turned = cv::imread(file, cv::IMREAD_COLOR);
			ASSERT_EQ(turned.size(), reference.size());
			EXPECT_GT(cv::norm(turned, reference, cv::NORM_INF), 0.0);
		}
		const cv::Mat read = decodeImageFile(file, "OMNICAM");
		ASSERT_EQ(read.size(), reference.size()) << int(orientation);
		EXPECT_EQ(cv::norm(read, reference, cv::NORM_INF), 0.0) << int(orientation);
	}
}

TEST(BadFiles, APngDecodesAsOpenCvDecodesItAndADamagedOneGivesOneReasonAndNoLinesOfLibpng)
{
	const std::string d = dir("png");
	cv::Mat colour(120, 160, CV_8UC3), grey8, colour16, grey16, rgba;
	cv::randu(colour, 0, 255);
	cv::cvtColor(colour, grey8, cv::COLOR_BGR2GRAY);
	cv::cvtColor(colour, rgba, cv::COLOR_BGR2BGRA);
	rgba.forEach<cv::Vec4b>([](cv::Vec4b& p, const int* at) { p[3] = static_cast<uchar>(at[1]); });
	colour.convertTo(colour16, CV_16UC3, 257.0, 3);  // a low byte that must be dropped, not rounded
	grey8.convertTo(grey16, CV_16UC1, 257.0);
	const std::vector<std::pair<std::string, std::vector<int>>> kinds = {
		{"colour", {}}, {"grey8", {}}, {"colour16", {}}, {"grey16", {}}, {"rgba", {}},
		{"bilevel", {cv::IMWRITE_PNG_BILEVEL, 1}}};
	const std::vector<cv::Mat> images = {colour, grey8, colour16, grey16, rgba, grey8 > 128};
	for (std::size_t k = 0; k < kinds.size(); ++k)
	{
		const std::string file = d + "/" + kinds[k].first + ".png";
		ASSERT_TRUE(cv::imwrite(file, images[k], kinds[k].second));
		for (const int flags : {cv::IMREAD_COLOR, cv::IMREAD_GRAYSCALE})
		{
			const cv::Mat ours = decodeImageFile(file, "OMNICAM", flags), theirs = cv::imread(file, flags);
			ASSERT_EQ(ours.size(), theirs.size()) << file;
			ASSERT_EQ(ours.type(), theirs.type()) << file;
			// Grey from colour: libpng's fixed-point weights and OpenCV's differ by one level at most.
			const bool converted = flags == cv::IMREAD_GRAYSCALE && images[k].channels() > 1;
			EXPECT_LE(cv::norm(ours, theirs, cv::NORM_INF), converted ? 1.0 : 0.0) << file << " flags " << flags;
		}
	}
	std::string bytes;
	{
		std::ifstream f(d + "/colour.png", std::ios::binary);
		bytes.assign(std::istreambuf_iterator<char>(f), {});
	}
	bytes.replace(bytes.size() / 2, 64, std::string(64, '\0'));  // inside the pixel data; the end chunk stays
	std::ofstream(d + "/damaged.png", std::ios::binary) << bytes;
	testing::internal::CaptureStderr();
	const std::string why = errorOf([&] { decodeImageFile(d + "/damaged.png", "OMNICAM"); });
	const std::string printed = testing::internal::GetCapturedStderr();
	EXPECT_NE(why.find("damaged.png' of OMNICAM is damaged: "), std::string::npos) << why;
	EXPECT_EQ(printed, "") << "libpng's own lines reach the user";
}

TEST(BadFiles, ABmpAPlainPgmAndAPamCutShortAreRefusedBeforeOpenCvPrintsAboutThem)
{
	const std::string d = dir("cut_kinds");
	cv::Mat img(40, 60, CV_8UC3);
	cv::randu(img, 0, 255);
	const std::vector<std::pair<std::string, std::vector<int>>> kinds = {
		{"bmp", {}}, {"pgm", {cv::IMWRITE_PXM_BINARY, 0}}, {"ppm", {cv::IMWRITE_PXM_BINARY, 0}}, {"pam", {}}};
	for (const auto& [ext, params] : kinds)
	{
		const std::string whole = d + "/whole." + ext, cut = d + "/cut." + ext;
		ASSERT_TRUE(cv::imwrite(whole, ext == "pgm" ? img.col(0).clone().reshape(1, 40) : img, params)) << ext;
		EXPECT_EQ(cv::norm(decodeImageFile(whole, "", cv::IMREAD_UNCHANGED), cv::imread(whole, cv::IMREAD_UNCHANGED),
						   cv::NORM_INF),
				  0.0)
			<< ext;
		std::ifstream in(whole, std::ios::binary);
		const std::string bytes((std::istreambuf_iterator<char>(in)), {});
		std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() * 2 / 3);
		testing::internal::CaptureStderr();
		const std::string why = errorOf([&] { decodeImageFile(cut, "OMNICAM"); });
		EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << ext << ": OpenCV's own lines reach the user";
		EXPECT_NE(why.find("cut." + ext + "' of OMNICAM is truncated"), std::string::npos) << why;
	}
	std::ofstream(d + "/two.bmp", std::ios::binary) << "BM";  // a BMP's signature and nothing more
	testing::internal::CaptureStderr();
	const std::string why = errorOf([&] { decodeImageFile(d + "/two.bmp", "OMNICAM"); });
	EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
	EXPECT_NE(why.find("two.bmp' of OMNICAM is truncated"), std::string::npos) << why;
}

TEST(BadFiles, AnImageWhoseHeaderAsksForTooManyPixelsIsRefusedBeforeDecoding)
{
	const std::string d = dir("huge");
	// A PNG signature and an IHDR chunk saying 20000 x 20000, then IEND.
	std::string png("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\x4e\x20\0\0\x4e\x20\x08\x02\0\0\0", 29);
	png += std::string("\0\0\0\0\0\0\0\0IEND\xae\x42\x60\x82", 16);
	std::ofstream(d + "/huge.png", std::ios::binary) << png;
	const std::string why = errorOf([&] { decodeImageFile(d + "/huge.png", "", cv::IMREAD_GRAYSCALE); });
	EXPECT_NE(why.find("20000x20000"), std::string::npos) << why;
	EXPECT_NE(why.find("huge.png"), std::string::npos) << why;
}

TEST(BadFiles, ATimeIsDecimalSecondsWithinMrptsClock)
{
	EXPECT_DOUBLE_EQ(parseTime("1700000000.25"), 1700000000.25);
	EXPECT_DOUBLE_EQ(parseTime("100"), 100);
	EXPECT_DOUBLE_EQ(parseTime("0.5"), 0.5);
	for (const std::string bad : {"0x10", "1e300", "1e3", "-5", "1.2.3", "", ".", "nan", "inf", "12s", "1,5", "999999999999"})
		EXPECT_THROW(parseTime(bad), std::invalid_argument) << bad;
}

TEST(BadFiles, ATextFileOfOneEndlessLineIsRefusedAtItsCap)
{
	const std::string d = dir("long_line");
	std::ofstream(d + "/laser.csv") << "100.0, 1, 2\n" << std::string(kMaxLineBytes + 10, '7') << "\n";
	int rows = 0;
	const std::string why = errorOf([&] { forEachDataLine(d + "/laser.csv", "laser log", [&](int, const std::string&) { ++rows; }); });
	EXPECT_NE(why.find("laser.csv:2: a line of more than 1 MB"), std::string::npos) << why;
	EXPECT_EQ(rows, 1);
	std::ofstream(d + "/ok.csv") << "1, 2\n3, 4";  // no newline at the end: still two rows
	rows = 0;
	forEachDataLine(d + "/ok.csv", "laser log", [&](int, const std::string&) { ++rows; });
	EXPECT_EQ(rows, 2);
}
