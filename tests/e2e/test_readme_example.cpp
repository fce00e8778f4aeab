// The README's library example: its lines are examples/scan_image.cpp's, and
// that program, given an image of the factory sample, makes the very scan
// omnirange-scan made of it (exposure compensation included).
#include "Programs.h"

#include "../common/FactorySample.h"

#include <omnirange/config/OptionsTable.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/serialization/CArchive.h>

#include <vector>

using namespace omnirange::e2e;

using omnirange::trimmed;
using omnirange::test::readText;

TEST(ReadmeExample, ItsLinesAreTheExampleProgramsInOrder)
{
	const std::string readme = readText(kSource + "/README.md");
	const auto start = readme.find("```cpp\n");
	ASSERT_NE(start, std::string::npos) << "README.md has no C++ example";
	std::istringstream block(readme.substr(start + 7, readme.find("```", start + 7) - start - 7));
	const std::string program = readText(kSource + "/examples/scan_image.cpp");
	std::size_t at = 0;
	int lines = 0;
	for (std::string line; std::getline(block, line);)
	{
		if (trimmed(line).empty() || trimmed(line).rfind("#include", 0) == 0) continue;
		const auto found = program.find(trimmed(line), at);
		EXPECT_NE(found, std::string::npos) << "README line not in examples/scan_image.cpp (in order): " << line;
		if (found != std::string::npos) at = found, ++lines;
	}
	EXPECT_GE(lines, 4);
}

TEST(ReadmeExample, ScansAnImageAsOmnirangeScanDoes)
{
	const std::string dir = workDir("readme_example");
	const std::string scanned = scannedFactorySample(dir);
	// The sixth image of the scanned rawlog and the scan omnirange-scan made of it.
	mrpt::io::CFileGZInputStream f(scanned);
	auto archive = mrpt::serialization::archiveFrom(f);
	std::string image;
	mrpt::obs::CObservation2DRangeScan::Ptr expected;
	for (int images = 0; !expected;)
	{
		const auto obj = archive.ReadObject();
		if (auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obj); img && ++images == 6)
			image = img->image.getExternalStorageFile();
		auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obj);
		if (!image.empty() && s && s->sensorLabel == "OMNISCAN") expected = s;
	}
	const RunResult r = run(q(OMNIRANGE_EXAMPLE_FILE) + " " + q(kSource + "/ini/factory.ini") + " " + q(dir + "/f.hist") +
							" " + q(kSource + "/rawlogs/factory-sample_Images/" + image));
	ASSERT_EQ(r.code, 0) << r.out;
	EXPECT_NE(r.out.find("exposure compensation on"), std::string::npos) << r.out.substr(0, 200);
	std::istringstream rows(r.out.substr(r.out.find('\n') + 1));
	std::size_t i = 0, hits = 0;
	for (std::size_t ray; rows >> ray;)
	{
		double range;
		int valid;
		rows >> range >> valid;
		ASSERT_LT(i, expected->getScanSize());
		EXPECT_NEAR(range, expected->getScanRange(i), 1e-5) << "ray " << i;
		EXPECT_EQ(valid != 0, expected->getScanRangeValidity(i)) << "ray " << i;
		hits += valid, ++i;
	}
	EXPECT_EQ(i, expected->getScanSize());
	EXPECT_GT(hits, 50u);
}
