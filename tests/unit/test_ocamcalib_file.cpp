// OCamCalib's calib_results.txt, read as the toolbox writes it, and its
// errors naming the line.
#include "../common/FactorySample.h"

#include <omnirange/train/OCamCalibFile.h>

#include <gtest/gtest.h>

#include <fstream>

using namespace omnirange;

namespace
{
const char* kResults =
	"#polynomial coefficients for the DIRECT mapping function (ocam_model.ss in MATLAB). These are used by cam2world\n"
	"\n"
	"5 -1.813360e+02 0.000000e+00 2.282686e-03 -1.962681e-06 7.543659e-09 \n"
	"\n"
	"#polynomial coefficients for the inverse mapping function (ocam_model.invpol in MATLAB). These are used by world2cam\n"
	"\n"
	"3 261.1 142.4 -3.2 \n"
	"\n"
	"#center: \"row\" and \"column\", starting from 0 (C convention)\n"
	"\n"
	"478.500000 641.250000\n"
	"\n"
	"#affine parameters \"c\", \"d\", \"e\"\n"
	"\n"
	"1.000200 0.000100 -0.000300\n"
	"\n"
	"#image size: \"height\" and \"width\"\n"
	"\n"
	"960 1280\n";

std::string write(const std::string& name, const std::string& text)
{
	const std::string path = test::freshDir("ocamcalib", name) + "/calib_results.txt";
	std::ofstream(path) << text;
	return path;
}
}  // namespace

TEST(OCamCalibFile, ReadsWhatTheToolboxWrites)
{
	const OCamCalibFile f = readOCamCalib(write("good", kResults));
	ASSERT_EQ(f.poly.size(), 5u);
	EXPECT_DOUBLE_EQ(f.poly[0], -181.336);
	EXPECT_DOUBLE_EQ(f.poly[4], 7.543659e-09);
	EXPECT_EQ(f.inverse.size(), 3u);
	EXPECT_DOUBLE_EQ(f.row, 478.5);
	EXPECT_DOUBLE_EQ(f.column, 641.25);
	EXPECT_DOUBLE_EQ(f.e, -0.0003);
	EXPECT_EQ(f.height, 960);
	EXPECT_EQ(f.width, 1280);
	// The camera: the column is cx, the row cy.
	const CameraParams cam = ocamCamera(f);
	EXPECT_EQ(cam.mirror_model, MirrorModel::OCamCalib);
	EXPECT_DOUBLE_EQ(cam.cx, 641.25);
	EXPECT_DOUBLE_EQ(cam.cy, 478.5);
	EXPECT_EQ(cam.image_width, 1280);
	EXPECT_NO_THROW(OmniCameraModel{cam});
}

TEST(OCamCalibFile, ABadFileIsNamedWithItsLine)
{
	const auto message = [](const std::string& name, const std::string& text) {
		try
		{
			readOCamCalib(write(name, text));
		}
		catch (const std::runtime_error& e)
		{
			return std::string(e.what());
		}
		return std::string("no error");
	};
	std::string bad = kResults;
	bad.replace(bad.find("5 -1.8"), 1, "6");  // says 6 coefficients, gives 5
	EXPECT_NE(message("count", bad).find("calib_results.txt:3: a polynomial line"), std::string::npos) << message("count", bad);
	bad = kResults;
	bad.replace(bad.find("960 1280"), 8, "960 wide");
	EXPECT_NE(message("text", bad).find("calib_results.txt:19: "), std::string::npos) << message("text", bad);
	EXPECT_NE(message("short", "3 -1 0 0.001\n").find("expected 5 value lines, found 1"), std::string::npos);
	EXPECT_THROW(readOCamCalib("/nonexistent/calib_results.txt"), std::runtime_error);
}
