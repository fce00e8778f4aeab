// Decoding only the box of the image the scan reads: the scan is that of
// the whole image, through every stock camera model and an off-centre one.
#include "../common/FactorySample.h"

#include <omnirange/core/Rangefinder.h>
#include <omnirange/io/ObservationImage.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <fstream>

using namespace omnirange;

namespace
{
const std::string kImage = test::kSource + "/rawlogs/factory-sample_Images/factory-sample_OMNICAM_0000";

struct Camera
{
	std::string name;
	RangefinderParams params;
};

std::vector<Camera> stockCameras()
{
	RangefinderParams para = RangefinderParams::loadFromFile(test::kIni, "rangefinder");
	para.exposure_compensation = para.exposure_check = true;  // its ring and its disc are read too
	RangefinderParams mei = RangefinderParams::loadFromFile(test::kSource + "/ini/factory-hyperbolic.ini", "rangefinder");
	mei.exposure_compensation = mei.exposure_check = true;
	RangefinderParams ocam = para;
	ocam.camera.mirror_model = MirrorModel::OCamCalib;
	ocam.camera.ocam_poly = {-para.camera.R / 2, 0.0, 1 / (2 * para.camera.R)};
	ocam.camera.ocam_affine = {1.02, 0.004, -0.003};  // an ellipse: the box is not a circle's
	RangefinderParams off = para;
	off.camera.cx += 57.5, off.camera.cy -= 31.25;
	return {{"paraboloid", para}, {"mei", mei}, {"ocamcalib", ocam}, {"off-centre", off}};
}

/** The floor's colours (the ring just beyond the base of `bgr`), with a
 * training light unlike the image's: exposure compensation acts. */
ColourModel floorColours(const RangefinderParams& p, const cv::Mat& bgr)
{
	const OmniCameraModel camera(p.camera);
	ColourHistogram h;
	for (const cv::Vec3b& c : FloorRing(camera, floorBeyondBase(camera, p.scanner)).colours(bgr)) h.addPixel(&c[0]);
	ColourModel m(h);
	m.reference = {90, 100, 110};
	return m;
}

/** Sample image `n` at the camera's size, written as JPEG with `params`. */
std::string sampleAs(int n, const CameraParams& cam, const std::vector<int>& params, const std::string& name)
{
	cv::Mat img = cv::imread(kImage + "0" + std::to_string(n) + ".jpg");
	cv::resize(img, img, {cam.image_width, cam.image_height});
	img += cv::Scalar::all(20);  // no pixel black: a black one in a decode is one not decoded
	const std::string path = test::freshDir("omnirange_region", name) + "/image.jpg";
	cv::imwrite(path, img, params);
	return path;
}

void expectSameRays(const RangeScan& a, const RangeScan& b)
{
	ASSERT_EQ(a.rays.size(), b.rays.size());
	for (std::size_t i = 0; i < a.rays.size(); ++i)
	{
		const Ray &x = a.rays[i], &y = b.rays[i];
		EXPECT_EQ(x.status, y.status) << "ray " << i;
		EXPECT_EQ(x.range, y.range) << "ray " << i;  // bit for bit, not within a tolerance
		EXPECT_EQ(x.hit_rho, y.hit_rho) << "ray " << i;
		EXPECT_EQ(x.confidence, y.confidence) << "ray " << i;
	}
}
}  // namespace

TEST(RegionDecoding, ScansAsTheWholeImageThroughEveryStockCamera)
{
	for (const Camera& c : stockCameras())
		for (const auto& [encoding, params] : std::vector<std::pair<std::string, std::vector<int>>>{
				 {"baseline", {cv::IMWRITE_JPEG_QUALITY, 85}},
				 {"progressive", {cv::IMWRITE_JPEG_QUALITY, 95, cv::IMWRITE_JPEG_PROGRESSIVE, 1}}})
			for (int n : {0, 7})
			{
				SCOPED_TRACE(c.name + ", " + encoding + ", image " + std::to_string(n));
				const std::string file = sampleAs(n, c.params.camera, params, c.name + "-" + encoding);
				const cv::Mat whole = decodeImageFile(file, "");
				const Rangefinder rf(c.params, floorColours(c.params, whole));
				const PixelBox box = rf.pixelsRead();
				const cv::Mat part = decodeImageFile(file, "", cv::IMREAD_COLOR, box);
				const cv::Rect read(box.left, box.top, box.right - box.left + 1, box.bottom - box.top + 1);
				EXPECT_EQ(cv::norm(whole(read), part(read), cv::NORM_INF), 0.0);
				// Only around the box was decoded: the far corners are black, the whole image's are not.
				EXPECT_EQ(part.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
				EXPECT_NE(whole.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
				EXPECT_LT(read.area(), whole.total() / 2);
				expectSameRays(rf.process(whole), rf.process(part));
			}
}

TEST(RegionDecoding, ABoxOutsideASmallerImageDecodesItWhole)
{
	const std::string file = test::freshDir("omnirange_region", "small") + "/small.png.jpg";
	cv::imwrite(file, cv::imread(kImage + "00.jpg")(cv::Rect(0, 0, 200, 100)));
	PixelBox box;
	box.left = 150, box.right = 400, box.top = 20, box.bottom = 300;
	EXPECT_EQ(cv::norm(decodeImageFile(file, ""), decodeImageFile(file, "", cv::IMREAD_COLOR, box), cv::NORM_INF), 0.0);
}

TEST(RegionDecoding, DamageInRowsTheScanReadsIsRefusedAndBelowThemIsNot)
{
	// Noise: the coded data is spread evenly over the rows, so a cut at 70-80 % of it is far below row 116.
	cv::Mat noise(768, 1024, CV_8UC3);
	cv::randu(noise, 0, 255);
	std::vector<uchar> buf;
	cv::imencode(".jpg", noise, buf);
	const std::string whole(buf.begin(), buf.end()), d = test::freshDir("omnirange_region", "damage");
	const std::size_t n = whole.size();
	std::ofstream(d + "/whole.jpg", std::ios::binary) << whole;
	std::ofstream(d + "/damaged.jpg", std::ios::binary) << whole.substr(0, n * 7 / 10) + whole.substr(n * 8 / 10);
	PixelBox top, bottom;
	top.left = 10, top.right = 100, top.top = 10, top.bottom = 100;
	bottom.left = 10, bottom.right = 100, bottom.top = 600, bottom.bottom = 700;
	const cv::Rect read(10, 10, 91, 91);
	const cv::Mat part = decodeImageFile(d + "/damaged.jpg", "", cv::IMREAD_COLOR, top);
	EXPECT_EQ(cv::norm(part(read), decodeImageFile(d + "/whole.jpg", "")(read), cv::NORM_INF), 0.0);
	for (const PixelBox& box : {bottom, PixelBox{}})
	{
		std::string why;
		try
		{
			decodeImageFile(d + "/damaged.jpg", "", cv::IMREAD_COLOR, box);
		}
		catch (const std::exception& e)
		{
			why = e.what();
		}
		EXPECT_NE(why.find("is damaged"), std::string::npos) << why;
	}
}
