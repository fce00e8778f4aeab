#include "omnirange_sim/Simulator.h"

#include "omnirange_sim/FloorTruth.h"
#include "omnirange_sim/OmniRenderer.h"
#include "omnirange_sim/Route.h"
#include "omnirange_sim/SensorModels.h"

#include <omnirange/io/AtomicWrite.h>
#include <omnirange/io/SensorLabels.h>
#include <omnirange/io/OutputRule.h>
#include <omnirange/io/RawlogWriter.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/serialization/CArchive.h>
#include <opencv2/core/utility.hpp>

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
constexpr char kProgram[] = "omnirange-sim";  // the outputs' owner (OutputRule.h)

std::string stemOf(const std::string& rawlog)
{
	const std::string dir = imagesDirFor(rawlog);
	return dir.substr(0, dir.size() - std::string("_Images").size());
}
}  // namespace

Simulator::Simulator() : mrpt::system::COutputLogger("omnirange-sim") {}

SimSummary Simulator::run(const SimOptions& o, const std::function<void(int, int)>& progress)
{
	const auto t0 = std::chrono::steady_clock::now();
	if (o.output.empty()) throw std::invalid_argument("no output rawlog given");
	if (o.threads < 1 || o.threads > 256) throw std::invalid_argument("threads must be within [1, 256]");
	if (o.max_frames < 0) throw std::invalid_argument("max_frames must be >= 0 (0: the whole route)");
	if (!(o.map_resolution > 0)) throw std::invalid_argument("map resolution must be > 0 m");

	// 1. Inputs: robot, world, route; all checked before anything is written,
	//    and none of them is an output.
	const std::string base = stemOf(o.output);
	const std::vector<std::string> inputs{o.world_file, o.route_file, o.robot_ini};
	requireRawlogOutputAllowed(o.output, kProgram, inputs, o.force);
	requireOutputsAllowed({{base + "_truemap.png", OutputKind::Image}, {base + "_truemap.gridmap.gz", OutputKind::GridMap}},
						  kProgram, inputs, o.force);
	RobotParams robot;
	if (!o.robot_ini.empty()) robot = RobotParams::loadFile(o.robot_ini);
	if (!o.image_format.empty())
	{
		robot.omnicam.format = o.image_format;
		robot.validate();
	}
	const World world = loadWorld(o.world_file);
	// The grid maps the world names are read as surely as the world: never an output.
	std::vector<std::string> with_maps = inputs;
	with_maps.insert(with_maps.end(), world.maps.begin(), world.maps.end());
	requireRawlogOutputAllowed(o.output, kProgram, with_maps, o.force);
	requireOutputsAllowed({{base + "_truemap.png", OutputKind::Image}, {base + "_truemap.gridmap.gz", OutputKind::GridMap}},
						  kProgram, with_maps, o.force);
	const Route route = loadRoute(o.route_file);
	checkRouteClear(route, world, robot.robot.clearance, robot.omnicam.camera.h);
	const double dt = 1.0 / robot.robot.frame_rate;
	auto poses = sampleTrajectory(route, robot.robot.speed, robot.robot.turn_rate, dt);
	if (o.max_frames > 0 && static_cast<int>(poses.size()) > o.max_frames) poses.resize(o.max_frames);
	MRPT_LOG_INFO_STREAM(
		"world '" << world.name << "': " << world.solids.size() << " solids; route "
				  << route.waypoints.size() << " waypoints, " << poses.size() << " frames");

	cv::setNumThreads(o.threads);
	const OmniRenderer renderer(world, robot);

	// 2. The frames: ODOMETRY, GT, OMNICAM, TRUTH, LASER at each pose.
	RawlogWriter out(o.output, kProgram);
	if (o.force) out.replaceAnyImagesFolder();
	OdometrySimulator odometry(robot.odometry, robot.robot.seed * 31u + 1u);
	std::mt19937_64 laser_rng(robot.robot.seed * 131u + 7u);
	const auto& cam = robot.omnicam;
	const std::string stem = std::filesystem::path(stemOf(o.output)).filename().string();
	for (std::size_t k = 0; k < poses.size(); ++k)
	{
		const auto stamp = mrpt::Clock::fromDouble(kEpoch + k * dt);
		const Pose2& pose = poses[k];

		// Odometry first: icp-slam takes the motion up to an instant from the
		// odometry before the scans taken at that instant.
		auto odo = odometry.step(pose);
		odo->timestamp = stamp;
		out.write(*odo);

		auto gt = groundTruth(pose);
		gt->timestamp = stamp;
		out.write(*gt);
		auto img = mrpt::obs::CObservationImage::Create();
		img->sensorLabel = kOmnicamLabel;
		img->timestamp = stamp;
		img->cameraPose = cam.pose;
		img->cameraParams.ncols = static_cast<uint32_t>(cam.camera.image_width);
		img->cameraParams.nrows = static_cast<uint32_t>(cam.camera.image_height);
		// MRPT has no catadioptric model: the focal length stored is the mirror's scale.
		const double f = cam.camera.mirror_model == MirrorModel::Mei ? cam.camera.gamma : cam.camera.R;
		img->cameraParams.setIntrinsicParamsFromValues(f, f, cam.camera.cx, cam.camera.cy);
		std::ostringstream name;
		name << stem << "_OMNICAM_" << std::setw(6) << std::setfill('0') << k << "." << cam.format;
		img->image = out.externalImage(renderer.render(pose, robot.robot.seed * 1000003ull + k, static_cast<int>(k)),
									   name.str(), cam.jpeg_quality);
		out.write(*img);

		auto truth = floorTruth(world, cam, pose, cam.truth_rays, cam.truth_max_range);
		truth->timestamp = stamp;
		out.write(*truth);

		auto laser = simulateLaser(world, robot.laser, pose, laser_rng);
		laser->timestamp = stamp;
		out.write(*laser);

		if (progress) progress(static_cast<int>(k + 1), static_cast<int>(poses.size()));
	}

	// 3. The true map, as an MRPT grid map and a PNG: staged, then committed
	//    with the rawlog and its images, so a failure leaves the old three whole.
	const auto grid = trueMap(world, o.map_resolution, robot.omnicam.camera.h);
	StagedFile map(base + "_truemap.gridmap.gz", [&](const std::string& tmp) {
		mrpt::io::CFileGZOutputStream f;
		if (!f.open(tmp)) throw std::runtime_error("cannot write '" + base + "_truemap.gridmap.gz'");
		mrpt::serialization::archiveFrom(f) << grid;
	});
	mrpt::img::CImage png;
	grid.getAsImage(png, true);  // north up, as saveAsBitmapFile() draws it
	StagedFile picture = stageImage(base + "_truemap.png", png.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY));
	out.commit();
	map.commit();
	picture.commit();

	SimSummary s;
	s.frames = static_cast<int>(poses.size());
	s.route_seconds = poses.size() * dt;
	s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	return s;
}

}  // namespace omnirange::sim
