// Writes the fuzz targets' generated seeds into fuzz/corpus/: small but
// complete histogram files (one- and two-class, with a reference colour) and
// rawlogs (observations-only gzip and plain, actions/sensory-frames) holding
// a scan, an embedded image and odometry. Run by hand when a format changes.

#include <omnirange/core/ColourModel.h>
#include <omnirange/io/RawlogWriter.h>

#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <opencv2/core.hpp>

#include <filesystem>

using namespace omnirange;

namespace
{
const std::string kCorpus = OMNIRANGE_FUZZ_CORPUS;

ColourHistogram histogram(ColourSpace space, int bins, int shade)
{
	ColourHistogram h(space, bins);
	for (int i = 0; i < 50; ++i)
	{
		const std::uint8_t bgr[3] = {static_cast<std::uint8_t>(shade + i), static_cast<std::uint8_t>(shade),
									 static_cast<std::uint8_t>(255 - shade - i)};
		h.addPixel(bgr);
	}
	return h;
}

std::vector<mrpt::obs::CObservation::Ptr> observations()
{
	auto scan = mrpt::obs::CObservation2DRangeScan::Create();
	scan->sensorLabel = "LASER";
	scan->timestamp = mrpt::Clock::fromDouble(1.0);
	scan->aperture = 2 * M_PI;
	scan->resizeScan(8);
	for (std::size_t i = 0; i < 8; ++i) scan->setScanRange(i, 1.0f + 0.25f * i), scan->setScanRangeValidity(i, i % 3 != 0);

	auto image = mrpt::obs::CObservationImage::Create();
	image->sensorLabel = "OMNICAM";
	image->timestamp = scan->timestamp;
	cv::Mat bgr(8, 8, CV_8UC3);
	cv::randu(bgr, 0, 255);
	image->image = mrpt::img::CImage(bgr, mrpt::img::DEEP_COPY);

	auto odo = mrpt::obs::CObservationOdometry::Create();
	odo->sensorLabel = "ODOMETRY";
	odo->timestamp = scan->timestamp;
	odo->odometry = mrpt::poses::CPose2D(0.5, 0.25, 0.1);
	return {odo, image, scan};
}
}  // namespace

int main()
{
	std::filesystem::create_directories(kCorpus + "/histogram");
	std::filesystem::create_directories(kCorpus + "/rawlog");
	ColourModel(histogram(ColourSpace::RGB, 4, 40)).save(kCorpus + "/histogram/one_class_rgb4.hist");
	ColourModel two(histogram(ColourSpace::Chroma, 6, 60), histogram(ColourSpace::Chroma, 6, 150));
	two.reference = {90.0, 100.5, 110.25};
	two.save(kCorpus + "/histogram/two_class_chroma6_reference.hist");

	{
		RawlogWriter w(kCorpus + "/rawlog/observations.rawlog.gz", "omnirange-fuzz-seeds");
		for (const auto& o : observations()) w.write(*o);
		w.commit();
	}
	{
		mrpt::io::CFileOutputStream f(kCorpus + "/rawlog/observations_plain.rawlog");
		auto a = mrpt::serialization::archiveFrom(f);
		for (const auto& o : observations()) a << *o;
	}
	{
		RawlogWriter w(kCorpus + "/rawlog/sensory_frames.rawlog.gz", "omnirange-fuzz-seeds");
		mrpt::obs::CActionCollection actions;
		mrpt::obs::CActionRobotMovement2D move;
		move.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0.05), {});
		actions.insert(move);
		mrpt::obs::CSensoryFrame frame;
		for (const auto& o : observations()) frame.insert(o);
		w.write(actions);
		w.write(frame);
		w.commit();
	}
	return 0;
}
