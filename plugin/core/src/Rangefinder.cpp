#include "omnirange/core/Rangefinder.h"

#include "omnirange/config/OptionsTable.h"

#include "omnirange/config/IniSectionWriter.h"
#include "omnirange/config/LayeredIni.h"
#include <mrpt/config/CConfigFile.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>

namespace omnirange
{
std::string toString(UnsureRays u) { return u == UnsureRays::Obstacle ? "obstacle" : "invalid"; }

UnsureRays unsureRaysFromString(const std::string& name)
{
	if (name == "obstacle") return UnsureRays::Obstacle;
	if (name == "invalid") return UnsureRays::Invalid;
	throw std::invalid_argument("unsure_rays must be 'obstacle' or 'invalid', not '" + name + "'");
}

const OptionsTable<RangefinderParams>& RangefinderParams::table()
{
	using P = RangefinderParams;
	static const auto t = OptionsTable<P>()
		.include(CameraParams::table(), [](P& p) -> auto& { return p.camera; })
		.include(PolarScannerParams::table(), [](P& p) -> auto& { return p.scanner; })
		.add("threshold", "-", "Theta of eq. (5): a colour is free floor when P(colour) >= Theta",
			 [](P& p) -> auto& { return p.threshold; })
		.within(kThresholdRange)
		.add("obstacle_ratio", "-",
			 "with obstacle colours in the histogram file: free also needs P(c|floor) >= obstacle_ratio * "
			 "P(c|obstacle); 0: the paper's one-class model",
			 [](P& p) -> auto& { return p.obstacle_ratio; })
		.within(kObstacleRatioRange)
		.add("histogram_smoothing", "bins",
			 "sigma of a Gaussian over the histogram's bins (floor and obstacle colours) before eq. (5); 0: as counted",
			 [](P& p) -> auto& { return p.histogram_smoothing; })
		.within(kSmoothingRange)
		.add("shadow_depth", "-",
			 "a colour is also free when it is a free floor colour in light down to 1 - shadow_depth times as "
			 "strong and training never saw it on an obstacle (the floor in shadow); 0: the colours "
			 "as trained",
			 [](P& p) -> auto& { return p.shadow_depth; })
		.within(kShadowDepthRange)
		.add("sure_floor_share", "-",
			 "the floor's most common colours that together hold this share of its training pixels are sure floor; "
			 "a free stretch crossing sure_run pixels of the others makes a ray unsure (1: every free colour is sure)",
			 [](P& p) -> auto& { return p.sure_floor_share; })
		.within(kSureShareRange)
		.add("sure_obstacle_ratio", "-",
			 "with obstacle colours in the histogram file, a free colour is sure floor only when also P(c|floor) >= "
			 "sure_obstacle_ratio * P(c|obstacle) (0: off)",
			 [](P& p) -> auto& { return p.sure_obstacle_ratio; })
		.within(kObstacleRatioRange)
		.addEnum("unsure_rays",
				 "how an unsure ray is written into the scan: obstacle (a valid return at its confident extent: a "
				 "navigator stops there) or invalid (its range that extent; a map with "
				 "considerInvalidRangesAsFreeSpace = false neither clears nor marks it)",
				 [](P& p) -> auto& { return p.unsure_rays; }, unsureRaysFromString,
				 {UnsureRays::Obstacle, UnsureRays::Invalid})
		.include(OutlierFilterParams::table(), [](P& p) -> auto& { return p.outliers; })
		.include(WallFitParams::table(), [](P& p) -> auto& { return p.walls; })
		.add("exposure_compensation", "bool",
			 "bring each image's floor just beyond the base back to its colour in training before classifying "
			 "(needs a histogram file that records it)",
			 [](P& p) -> auto& { return p.exposure_compensation; })
		.add("exposure_check", "bool",
			 "drop exposure compensation's gains when, out to max range, they leave fewer than 90 % of the pixels "
			 "free that no gains do (a shadow on the ring around the base is not a change of light)",
			 [](P& p) -> auto& { return p.exposure_check; })
		.add("exposure_deadband", "-",
			 "the exposure compensation leaves an image as it is when every channel's gain is within this of 1",
			 [](P& p) -> auto& { return p.exposure_deadband; })
		.within(Range::openHigh(0, 1))
		.add("floor_adaptation", "bool",
			 "also call free the colours of the floor just beyond the base in recent images (no laser needed; "
			 "omnirange-scan and the sensor, in image order)",
			 [](P& p) -> auto& { return p.floor_adaptation; })
		.add("adaptation_memory", "images",
			 "with floor_adaptation: how many images a floor colour seen once takes to fade to 1/e",
			 [](P& p) -> auto& { return p.adaptation_memory; })
		.within(Range::closed(1, 1e6))
		.add("sensor_label", "-", "sensorLabel of the produced CObservation2DRangeScan",
			 [](P& p) -> auto& { return p.sensor_label; })
		.addPose("the omnicam's pose on the robot: the scan's sensorPose (pose_z defaults to h when absent)",
				 [](P& p) -> auto& { return p.sensor_pose; })
		.add("std_error", "m", "stdError written into each scan", [](P& p) -> auto& { return p.std_error; })
		.within(Range::atLeast(0));
	return t;
}

RangefinderParams RangefinderParams::loadFromFile(const std::string& path, const std::string& section)
{
	requireRegularFile(path, "ini file");
	if (!std::filesystem::is_regular_file(path)) throw std::runtime_error("cannot open ini file '" + path + "'");
	RangefinderParams p;
	const LayeredIni ini = readLayeredIni(path);
	try
	{
		p.loadFromConfig(*ini.merged, section);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(namingItsFile(ini, path, e));
	}
	return p;
}

void RangefinderParams::requireWritable(const std::string& path, const std::string& section)
{
	requireSectionName(section);
	if (!std::filesystem::exists(path)) return;
	try
	{
		if (requireWellFormedIni(path) == 0) return;  // an empty file waits for its first keys
		// Its bases too: keys saved into an ini that does not load would be read by nothing, and its camera is
		// unknown to whoever checks the keys against it.
		if (!iniBaseOf(path).empty()) (void)readLayeredIni(path);
		const mrpt::config::CConfigFile ini(path);  // its own keys: the section written is in it
		RangefinderParams p;
		if (ini.sectionExists(section)) table().load(p, ini, section);
	}
	catch (const std::exception& e)
	{
		const std::string what = e.what();
		throw std::runtime_error(what.rfind(path, 0) == 0 ? what : path + ": " + what);
	}
}

void RangefinderParams::loadFromConfig(const mrpt::config::CConfigFileBase& c, const std::string& s,
									   const std::vector<std::string>& also_allowed)
{
	table().load(*this, c, s, also_allowed);
	// pose_z defaults to h: the viewpoint is on the camera's axis at that height.
	std::vector<std::string> present;
	c.getAllKeys(s, present);
	if (std::find(present.begin(), present.end(), "pose_z") == present.end()) sensor_pose.z(camera.h);
	try
	{
		validate();
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument("[" + s + "] " + e.what());
	}
}

void RangefinderParams::validate() const
{
	// The camera model and the scanner check their keys as they are made, and the scanner that its circle
	// (N, K, max_range and the camera at once) fits in the image.
	PolarScanner(OmniCameraModel(camera), scanner);
	validateRest();
}

void RangefinderParams::validateRest() const
{
	outliers.validate();
	walls.validate();
	table().requireRanges(*this);
	require(!sensor_label.empty(), "sensor_label is empty");
}

std::string RangefinderParams::asIni() const { return table().print(*this); }

std::string RangefinderParams::changes() const
{
	RangefinderParams defaults;
	defaults.sensor_pose.z(camera.h);  // pose_z follows h unless set
	return table().printChanges(*this, defaults);
}

int RangeScan::count(RayStatus s) const
{
	return static_cast<int>(std::count_if(
		rays.begin(), rays.end(), [s](const Ray& r) { return r.status == s; }));
}

double floorBeyondBase(const OmniCameraModel& camera, const PolarScannerParams& scanner)
{
	return camera.distanceFromRho(scanner.base_radius) + 0.05;
}

Rangefinder::Rangefinder(const RangefinderParams& params, const ColourModel& colours)
	: p_((params.validateRest(), params)),  // camera_ and scanner_ check the rest as they are made
	  camera_(p_.camera),
	  classifier_(colours, p_.threshold, p_.obstacle_ratio, p_.histogram_smoothing, p_.shadow_depth,
				  p_.sure_floor_share, p_.sure_obstacle_ratio),
	  scanner_(camera_, p_.scanner),
	  reference_(colours.reference),
	  compensate_(p_.exposure_compensation && colours.hasReference()),
	  ring_(camera_, floorBeyondBase(camera_, p_.scanner)),
	  check_disc_(camera_, floorBeyondBase(camera_, p_.scanner),
				  std::max(1.0, camera_.rhoFromDistance(p_.scanner.max_range) -
									camera_.rhoFromDistance(floorBeyondBase(camera_, p_.scanner))),
				  4.0)
{
	if (p_.floor_adaptation) adaptation_.emplace(classifier_, p_.adaptation_memory);
}

std::optional<FreeSpaceClassifier> Rangefinder::learnFloor(const cv::Mat& bgr)
{
	if (!adaptation_) return std::nullopt;
	scanner_.checkImage(bgr);
	adaptation_->learn(ring_.colours(bgr), classifier_.binner());
	return adaptation_->classifier(classifier_);
}

RangeScan Rangefinder::processNext(const cv::Mat& bgr)
{
	const auto adapted = learnFloor(bgr);
	return process(bgr, adapted ? &*adapted : nullptr);
}

PixelBox Rangefinder::pixelsRead() const
{
	PixelBox box = scanner_.pixelsRead();
	box.add(ring_.pixelsRead());
	box.add(check_disc_.pixelsRead());
	return box;
}

void Rangefinder::withClassifierFor(const cv::Mat& bgr, const PixelClassifier* adapted,
								   const std::function<void(const PixelClassifier&)>& use) const
{
	const PixelClassifier& classifier = adapted ? *adapted : static_cast<const PixelClassifier&>(classifier_);
	if (!compensate_) return use(classifier);
	const auto gains = compensatingGains(reference_, ring_.medianColour(bgr), p_.exposure_deadband);
	if (gains == std::array<double, 3>{1.0, 1.0, 1.0}) return use(classifier);  // within the dead band
	const CompensatedClassifier compensated(classifier, gains);
	// Gains that lose a clear share of the floor were asked for by a shadow
	// on the ring, not by the light.
	if (p_.exposure_check &&
		check_disc_.countFree(bgr, compensated) < kExposureCheckShare * check_disc_.countFree(bgr, classifier))
		return use(classifier);
	use(compensated);
}

RangeScan Rangefinder::process(const cv::Mat& bgr, const PixelClassifier* adapted, StageTimes* times) const
{
	using Clock = std::chrono::steady_clock;
	Clock::time_point last = times ? Clock::now() : Clock::time_point();
	const auto lap = [&](double StageTimes::*stage) {  // only when asked: the hot path reads no clock
		if (!times) return;
		const auto now = Clock::now();
		times->*stage = std::chrono::duration<double, std::milli>(now - last).count();
		last = now;
	};
	scanner_.checkImage(bgr);
	RangeScan out;
	// 0. Light: see the image as if in training's light, through the floor
	//    just beyond the base (ExposureCompensation.h).
	// 1-3. Classify the pixels along each polar scanline (eq. (5)), find
	//      where the floor ends with the N/K filters (Fig. 3), and convert
	//      that pixel to metres (eq. (6)).
	withClassifierFor(bgr, adapted, [&](const PixelClassifier& seen) {
		lap(&StageTimes::light);
		out.rays = scanner_.scan(bgr, seen);
		lap(&StageTimes::scan);
	});
	// 4. Reject the rays that disagree with both their neighbours.
	out.outliers = rejectOutliers(out.rays, p_.outliers);
	lap(&StageTimes::outliers);
	// 5. Thin walls: hits on one straight wall onto its fitted line.
	out.wall_fitted = fitWalls(out.rays, camera_, p_.walls, p_.scanner.min_range, p_.scanner.max_range);
	lap(&StageTimes::walls);
	// 6. Doubt (beyond the paper, which §VI names the limit): a ray whose
	//    free stretch crosses colours the floor rarely shows claims free
	//    floor only up to where they start.
	for (Ray& ray : out.rays) markUnsure(ray, p_.scanner.min_range);
	return out;
}

void markUnsure(Ray& ray, double min_range)
{
	if (ray.sure_end < 0 || (ray.status != RayStatus::Hit && ray.status != RayStatus::NoHit)) return;
	const float extent = std::max(ray.sure_range, static_cast<float>(min_range));
	// A hit the edge bias or the wall fit moved in to the doubt's start claims no doubtful floor.
	if (ray.status == RayStatus::Hit && extent >= ray.range) return;
	ray.confidence = std::clamp(extent / std::max(ray.range, 1e-3f), 0.0f, 0.99f);
	ray.status = RayStatus::Unsure;
	ray.range = extent;
}

mrpt::obs::CObservation2DRangeScan::Ptr Rangefinder::toObservation(
	const RangeScan& scan, mrpt::Clock::time_point stamp) const
{
	auto obs = mrpt::obs::CObservation2DRangeScan::Create();
	const int S = static_cast<int>(scan.rays.size());
	obs->sensorLabel = p_.sensor_label;
	obs->timestamp = stamp;
	obs->sensorPose = p_.sensor_pose;
	obs->aperture = static_cast<float>(scanAperture(S));
	obs->rightToLeft = true;
	obs->maxRange = static_cast<float>(p_.scanner.max_range);
	obs->stdError = static_cast<float>(p_.std_error);
	obs->resizeScan(S);
	for (int i = 0; i < S; ++i)
	{
		const Ray& ray = scan.rays[i];
		obs->setScanRange(i, ray.range);
		obs->setScanRangeValidity(
			i, ray.status == RayStatus::Hit || (ray.status == RayStatus::Unsure && p_.unsure_rays == UnsureRays::Obstacle));
		obs->setScanIntensity(i, static_cast<int32_t>(std::lround(kFullConfidence * ray.confidence)));
	}
	obs->setScanHasIntensity(true);
	return obs;
}

}  // namespace omnirange
