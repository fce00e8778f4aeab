#include "omnirange_sim/Simulator.h"

#include "omnirange_sim/FloorTruth.h"
#include "omnirange_sim/OmniRenderer.h"
#include "omnirange_sim/Route.h"
#include "omnirange_sim/SensorModels.h"

#include <omnirange/config/Output.h>
#include <omnirange/io/ImageFile.h>
#include <omnirange/config/OptionsTable.h>
#include <omnirange/config/SensorLabels.h>
#include <omnirange/core/Threads.h>
#include <omnirange/io/RawlogWriter.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/serialization/CArchive.h>
#include <opencv2/core/utility.hpp>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace omnirange::sim
{
namespace
{
constexpr double kEpoch = 1767225600.0;  // 2026-01-01T00:00:00Z: timestamps start here
constexpr char kProgram[] = "omnirange-sim";  // the outputs' owner (config/Output.h)

/** The rawlog's path without ".rawlog", through a link to it: the true maps go
 * beside the file written, as its images folder does. */
std::string stemOf(const std::string& rawlog)
{
	const std::string dir = imagesDirFor(std::filesystem::is_symlink(rawlog) ? fileLedTo(rawlog) : rawlog);
	return dir.substr(0, dir.size() - std::string("_Images").size());
}
}  // namespace

Simulator::Simulator() : mrpt::system::COutputLogger("omnirange-sim") {}

namespace
{
/** What a run simulates, read and checked before anything is written. */
struct SimInputs
{
	RobotParams robot;
	World world;
	std::size_t waypoints{0};
	std::vector<Pose2> poses;
	double dt{0};  ///< [s] between frames
};

/** Robot, world and route, all checked before anything is written, and none of them an output. */
SimInputs readInputs(const SimOptions& o)
{
	require(!o.output.empty(), "no output rawlog given");
	require(o.threads >= 1 && o.threads <= 256, "threads must be within [1, 256]");
	require(o.max_frames >= 0, "max_frames must be >= 0 (0: the whole route)");
	require(o.map_resolution > 0, "map resolution must be > 0 m");
	const std::string base = stemOf(o.output);
	std::vector<std::string> inputs{o.world_file, o.route_file, o.robot_ini};
	const auto requireOutputs = [&] {
		requireRawlogOutputAllowed(o.output, kProgram, inputs, o.force);
		// A true map through a link onto the rawlog or into its images would be replaced by them, or they by it.
		requireOutputsAllowed({{o.output, OutputKind::Rawlog}, {base + "_Images", OutputKind::Folder},
							   {base + "_truemap.png", OutputKind::Image}, {base + "_truemap.gridmap.gz", OutputKind::GridMap}},
							  kProgram, inputs, o.force);
	};
	requireOutputs();
	SimInputs in;
	if (!o.robot_ini.empty()) in.robot = RobotParams::loadFile(o.robot_ini);
	if (!o.image_format.empty())
	{
		in.robot.omnicam.format = o.image_format;
		in.robot.validate();
	}
	in.world = loadWorld(o.world_file);
	// The grid maps the world names are read as surely as the world: never an output.
	inputs.insert(inputs.end(), in.world.maps.begin(), in.world.maps.end());
	requireOutputs();
	const Route route = loadRoute(o.route_file);
	checkRouteClear(route, in.world, in.robot.robot.clearance, in.robot.omnicam.camera.h);
	in.waypoints = route.waypoints.size();
	in.dt = 1.0 / in.robot.robot.frame_rate;
	try
	{
		in.poses = sampleTrajectory(route, in.robot.robot.speed, in.robot.robot.turn_rate, in.dt, o.max_frames);
	}
	catch (const std::runtime_error& e)
	{
		throw std::runtime_error("'" + o.route_file + "': " + e.what());
	}
	return in;
}

/** The omnicam's observation of a rendered `image`, written as the external file `name`. */
mrpt::obs::CObservationImage::Ptr omnicamImage(const OmnicamSimParams& cam, RawlogWriter& out, const cv::Mat& image,
											   const std::string& name)
{
	auto img = mrpt::obs::CObservationImage::Create();
	img->sensorLabel = kOmnicamLabel;
	img->cameraPose = cam.pose;
	img->cameraParams.ncols = static_cast<uint32_t>(cam.camera.image_width);
	img->cameraParams.nrows = static_cast<uint32_t>(cam.camera.image_height);
	// MRPT has no catadioptric model: the focal length stored is the mirror's scale.
	const double f = cam.camera.mirror_model == MirrorModel::Mei ? cam.camera.gamma : cam.camera.R;
	img->cameraParams.setIntrinsicParamsFromValues(f, f, cam.camera.cx, cam.camera.cy);
	img->image = out.externalImage(image, name, cam.jpeg_quality);
	return img;
}
}  // namespace

SimSummary Simulator::run(const SimOptions& o, const std::function<void(int, int)>& progress)
{
	const auto t0 = std::chrono::steady_clock::now();
	const SimInputs in = readInputs(o);
	const RobotParams& robot = in.robot;
	MRPT_LOG_INFO_STREAM("world '" << in.world.name << "': " << in.world.solids.size() << " solids; route "
								   << in.waypoints << " waypoints, " << in.poses.size() << " frames");
	useThreads(o.threads);
	const OmniRenderer renderer(in.world, robot);

	// The frames: ODOMETRY, GT, OMNICAM, TRUTH, BODY, LASER at each pose.
	RawlogWriter out(o.output, kProgram, o.force);
	OdometrySimulator odometry(robot.odometry, robot.robot.seed * 31u + 1u);
	std::mt19937_64 laser_rng(robot.robot.seed * 131u + 7u);
	const auto& cam = robot.omnicam;
	const std::string stem = std::filesystem::path(stemOf(o.output)).filename().string();
	for (std::size_t k = 0; k < in.poses.size(); ++k)
	{
		const auto stamp = mrpt::Clock::fromDouble(kEpoch + k * in.dt);
		const Pose2& pose = in.poses[k];
		std::ostringstream name;
		name << stem << "_OMNICAM_" << std::setw(6) << std::setfill('0') << k << "." << cam.format;
		// Odometry first: icp-slam takes the motion up to an instant from the
		// odometry before the scans taken at that instant.
		const mrpt::obs::CObservation::Ptr frame[] = {
			odometry.step(pose), groundTruth(pose),
			omnicamImage(cam, out, renderer.render(pose, robot.robot.seed * 1000003ull + k, static_cast<int>(k)), name.str()),
			floorTruth(in.world, cam, pose, cam.truth_rays, cam.truth_max_range),
			bodyTruth(in.world, cam, pose, cam.truth_rays, cam.truth_max_range, robot.robot.strike_height),
			simulateLaser(in.world, robot.laser, pose, laser_rng)};
		for (const auto& obs : frame) obs->timestamp = stamp, out.write(*obs);
		if (progress) progress(static_cast<int>(k + 1), static_cast<int>(in.poses.size()));
	}

	// The true map, as an MRPT grid map and a PNG, goes in with the rawlog:
	// no rawlog is ever beside another run's true map.
	const std::string base = stemOf(o.output);
	const auto grid = trueMap(in.world, o.map_resolution, robot.omnicam.camera.h);
	out.outputs().write({base + "_truemap.gridmap.gz", OutputKind::GridMap}, [&](const std::string& tmp) {
		{
			mrpt::io::CFileGZOutputStream f;
			errno = 0;
			if (!f.open(tmp)) throw std::runtime_error(cannotWrite(base + "_truemap.gridmap.gz"));
			mrpt::serialization::archiveFrom(f) << grid;
		}
		requireWholeGzipFile(tmp, base + "_truemap.gridmap.gz");  // the stream reports no failed write
	});
	mrpt::img::CImage png;
	grid.getAsImage(png, true);  // north up, as saveAsBitmapFile() draws it
	stageImage(out.outputs(), base + "_truemap.png", png.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY));
	out.commit();

	SimSummary s;
	s.frames = static_cast<int>(in.poses.size());
	s.route_seconds = in.poses.size() * in.dt;
	s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	return s;
}

}  // namespace omnirange::sim
