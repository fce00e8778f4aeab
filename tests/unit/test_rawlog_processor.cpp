// The one rawlog loop: hooks by class and label, pairing by time, the
// actions/sensory-frames format opened into observations, stop().
#include <omnirange/io/RawlogProcessor.h>
#include <omnirange/io/RawlogWriter.h>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace omnirange;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationOdometry;

namespace
{
std::string tmpFile(const std::string& name)
{
	const auto dir = std::filesystem::temp_directory_path() / "omnirange_processor_test";
	std::filesystem::create_directories(dir);
	return (dir / name).string();
}

CObservation2DRangeScan::Ptr scan(const std::string& label, double t)
{
	auto s = CObservation2DRangeScan::Create();
	s->sensorLabel = label;
	s->timestamp = mrpt::Clock::fromDouble(t);
	return s;
}
}  // namespace

TEST(RawlogProcessor, HooksSeeTheirClassAndLabelAndPairsPairOnce)
{
	const std::string file = tmpFile("obs.rawlog");
	{
		RawlogWriter w(file, "omnirange-test");
		// A/B at 0.0, 0.05 pair; the lone A at 1.0 does not; B at 2.0 pairs with A at 2.08.
		for (const auto& [label, t] : std::vector<std::pair<std::string, double>>{
				 {"A", 0.0}, {"B", 0.05}, {"A", 1.0}, {"B", 2.0}, {"A", 2.08}, {"C", 2.09}})
			w.write(*scan(label, t));
		auto odo = CObservationOdometry::Create();
		odo->sensorLabel = "ODO";
		w.write(*odo);
		w.commit();
	}
	RawlogProcessor loop(file);
	int a = 0, any = 0, odometry = 0;
	std::vector<std::pair<double, double>> pairs;
	loop.on<CObservation2DRangeScan>("A", [&](const CObservation2DRangeScan::Ptr&) { ++a; });
	loop.on<CObservation2DRangeScan>("", [&](const CObservation2DRangeScan::Ptr&) { ++any; });
	loop.on<CObservationOdometry>("ODO", [&](const CObservationOdometry::Ptr&) { ++odometry; });
	loop.onPair<CObservation2DRangeScan, CObservation2DRangeScan>(
		"A", "B", 0.1, [&](const CObservation2DRangeScan::Ptr& x, const CObservation2DRangeScan::Ptr& y) {
			pairs.emplace_back(mrpt::Clock::toDouble(x->timestamp), mrpt::Clock::toDouble(y->timestamp));
		});
	loop.run();
	EXPECT_EQ(a, 3);
	EXPECT_EQ(any, 6);
	EXPECT_EQ(odometry, 1);
	ASSERT_EQ(pairs.size(), 2u);
	EXPECT_NEAR(pairs[0].first, 0.0, 1e-6);
	EXPECT_NEAR(pairs[1].second, 2.0, 1e-6);
	EXPECT_EQ(loop.objectsRead(), 7u);
	EXPECT_NE(loop.describeLabels().find("A, B, C, ODO"), std::string::npos) << loop.describeLabels();
}

TEST(RawlogProcessor, SensoryFramesAreOpenedAndStopEndsTheLoop)
{
	const std::string file = tmpFile("sf.rawlog");
	{
		RawlogWriter w(file, "omnirange-test");
		for (int i = 0; i < 3; ++i)
		{
			w.write(mrpt::obs::CActionCollection());
			mrpt::obs::CSensoryFrame sf;
			sf.insert(scan("LASER", i));
			sf.insert(scan("OTHER", i));
			w.write(sf);
		}
		w.commit();
	}
	RawlogProcessor loop(file);
	int lasers = 0, objects = 0;
	loop.onObject([&](const auto&) { ++objects; });
	loop.on<CObservation2DRangeScan>("LASER", [&](const CObservation2DRangeScan::Ptr&) {
		if (++lasers == 2) loop.stop();
	});
	loop.run();
	EXPECT_EQ(lasers, 2);
	EXPECT_EQ(objects, 4);  // action, frame, action, frame: then stopped
}
