#pragma once
// The omnicam rangefinder: colour image in, 2D range scan out. It owns the
// camera model, the free-space classifier and the polar scanner, and runs
// the paper's steps in order (see process()).

#include <omnirange/core/CameraModel.h>
#include <omnirange/core/ColourModel.h>
#include <omnirange/core/ExposureCompensation.h>
#include <omnirange/core/FloorAdaptation.h>
#include <omnirange/core/FreeSpaceClassifier.h>
#include <omnirange/core/OutlierFilter.h>
#include <omnirange/core/WallFit.h>
#include <omnirange/core/PolarScanner.h>
#include <omnirange/config/SensorLabels.h>

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <optional>
#include <string>
#include <vector>

namespace cv
{
class Mat;
}

namespace omnirange
{
/** How an unsure ray goes into the MRPT scan (toObservation). */
enum class UnsureRays
{
	/** a valid return at its confident extent: a navigator stops there */
	Obstacle,
	/** invalid, its range the confident extent: a map built with
	 * considerInvalidRangesAsFreeSpace = false neither clears nor marks it */
	Invalid
};
std::string toString(UnsureRays u);
UnsureRays unsureRaysFromString(const std::string& name);

/** [-] A scan's intensity channel carries each ray's confidence times this:
 * kFullConfidence for a hit or free ray, less for an unsure one. */
inline constexpr int kFullConfidence = 100;

/** Whether ray i of an MRPT scan is unsure: its intensity, when it has one,
 * below kFullConfidence (a laser's scan, or one without intensity, has none). */
inline bool rayIsUnsure(const mrpt::obs::CObservation2DRangeScan& scan, std::size_t i)
{
	return scan.hasIntensity() && scan.getScanIntensity(i) < kFullConfidence;
}

/** Makes every unsure ray of `scan` invalid (its range, the confident extent,
 * kept): what a map or a scan matcher takes from a scan written with
 * unsure_rays = obstacle. */
inline void invalidateUnsureRays(mrpt::obs::CObservation2DRangeScan& scan)
{
	for (std::size_t i = 0; i < scan.getScanSize(); ++i)
		if (rayIsUnsure(scan, i)) scan.setScanRangeValidity(i, false);
}

/** The ini section the rangefinder's keys are read from unless a program is told another. */
inline constexpr char kRangefinderSection[] = "rangefinder";

/** Every parameter of the rangefinder, read from one ini section whose keys
 * equal the member names (docs/parameters.md lists them; ini/maze.ini is a
 * commented example). */
struct RangefinderParams
{
	CameraParams camera;
	PolarScannerParams scanner;
	OutlierFilterParams outliers;
	WallFitParams walls;  ///< thin walls (WallFit.h)
	double threshold{0.05};  ///< Theta of eq. (5) [-] (the maze's, paper Table I)
	/** [-] with obstacle colours in the model: free also needs
	 * P(c | floor) >= obstacle_ratio * P(c | obstacle); 0: the paper's one-class model. */
	double obstacle_ratio{1.0};
	/** [bins] sigma of a Gaussian over the histogram's bins before eq. (5):
	 * a colour next to the floor's is nearly as likely as they are, so a
	 * small change of light or a darker far floor does not fall out of a
	 * handful of bins; 0: the paper's histogram as counted. */
	double histogram_smoothing{0.0};
	/** [-] a colour is also free when it is a free floor colour in light
	 * down to 1 - shadow_depth times as strong and training never saw it on
	 * an obstacle (FreeSpaceClassifier.h): the floor in a shadow training
	 * did not see, as the sun's patches move through a room. Off by
	 * default: the guard is only as good as the obstacles training saw, and
	 * after a short training the darker colours let obstacles through
	 * (docs/results.md). 0: the colours as trained. */
	double shadow_depth{0.0};
	/** [-] the floor's most common colours that together hold this share of
	 * its training pixels are sure floor; a free stretch that crosses
	 * scanner.sure_run pixels of the rest makes a ray unsure (1: every free
	 * colour is sure). omnirange-train --learn chooses it. */
	double sure_floor_share{0.98};
	/** [-] with obstacle colours in the model, a free colour is sure floor
	 * only when also P(c | floor) >= sure_obstacle_ratio * P(c | obstacle):
	 * the obstacles' feet show it rarely; 0: off. --learn chooses it. */
	double sure_obstacle_ratio{0.0};
	/** How unsure rays are written into the MRPT scan. */
	UnsureRays unsure_rays{UnsureRays::Obstacle};
	/** Bring each image's floor, just beyond the base, back to the colour it
	 * had in training before classifying (ExposureCompensation.h); only with
	 * a histogram file that records that colour. On by default: cameras'
	 * exposure and white balance drift, and in ordinary rooms mending that
	 * is worth far more than what it breaks where the robot stands in a
	 * shadow and looks into light (docs/results.md measures both). */
	bool exposure_compensation{true};
	/** [-] ...and leaves an image as it is when every channel's gain is
	 * within this of 1 (compensatingGains()). */
	double exposure_deadband{0.03};
	/** ...and drops the gains when, out to max range, they leave fewer than
	 * kExposureCheckShare of the pixels free that no gains do: a ring in a
	 * shadow the rest of the floor is not in (the robot beside a cabinet,
	 * under a table's edge) asks for gains that would brighten the lit
	 * floor out of its colours. */
	bool exposure_check{true};
	/** Adapt to the floor seen around the base in recent images
	 * (FloorAdaptation.h); off by default (docs/results.md measures it). */
	bool floor_adaptation{false};
	double adaptation_memory{50.0};  ///< [images] with floor_adaptation
	std::string sensor_label{kOmniscanLabel};  ///< label of the produced scans
	/** The omnicam's pose on the robot, which becomes the scan's sensorPose
	 * (MRPT's pose_* keys). pose_z defaults to camera h. */
	mrpt::poses::CPose3D sensor_pose{0, 0, 0.931, 0, 0, 0};
	/** [m] stdError written into each scan (about the paper's measured mean
	 * absolute difference). */
	double std_error{0.10};

	static const OptionsTable<RangefinderParams>& table();
	/** [section] of the ini file `path`, strictly: throws std::runtime_error
	 * "PATH: why" if the file is missing, a key repeats or a value is bad. */
	static RangefinderParams loadFromFile(const std::string& path, const std::string& section);
	/** Before keys are written into [section] of the ini `path`: throws
	 * std::runtime_error "PATH: why" if the file is malformed or its section
	 * holds a key loading refuses (an unknown key, a value that does not
	 * parse or is out of its range), so that no keys are added to an ini
	 * every program would then refuse. A missing or empty file or section
	 * passes; its bases and keys other keys bound are not judged (the
	 * section may wait for the keys about to be written). */
	static void requireWritable(const std::string& path, const std::string& section);
	/** Reads every key of `section`; throws std::invalid_argument naming the
	 * section and key on an unknown key (one not ours nor in `also_allowed`),
	 * an unparsable or an impossible value. */
	void loadFromConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
						const std::vector<std::string>& also_allowed = {});
	/** Throws std::invalid_argument on the first impossible value or
	 * combination (the scan circle must fit in the image): the one check
	 * loading and the tuner run. The camera model and the scanner check their
	 * own keys as they are made; then validateRest(). */
	void validate() const;
	/** validate() but for the camera model and the scanner: what the
	 * Rangefinder's constructor runs before it makes them. */
	void validateRest() const;
	/** One "key = value" line per parameter, in ini syntax. */
	std::string asIni() const;
	/** "key=value key=value ..." for the parameters that differ from their defaults, on one line. */
	std::string changes() const;
};

/** What one image produced. */
struct RangeScan
{
	std::vector<Ray> rays;  ///< S rays, in scanline order
	int outliers{0};  ///< rays the outlier filter rejected
	int wall_fitted{0};  ///< hits moved onto a fitted wall line
	int count(RayStatus s) const;
};

/** [ms] What each stage of one Rangefinder::process() call took: the light
 * (exposure compensation and its check), the scanlines (classification and
 * the search for the floor's end), the outlier filter and the wall fit. */
struct StageTimes
{
	double light{0}, scan{0}, outliers{0}, walls{0};
};

/** exposure_check keeps the gains unless they leave fewer than this share
 * of the floor pixels free that no gains do: the ring's gains are the
 * default, and only a clear loss overrules them. */
inline constexpr double kExposureCheckShare = 0.9;

/** [m] The floor just beyond the robot's base: 5 cm past base_radius, so
 * that the base's own edge is never counted. Training counts floor pixels
 * from here and exposure compensation reads its ring here. */
double floorBeyondBase(const OmniCameraModel& camera, const PolarScannerParams& scanner);

/** Step 6 of Rangefinder::process: a hit or free ray whose sure floor ends
 * before its end (Ray::sure_end) becomes Unsure at that extent (at least
 * min_range), its confidence the share of its claimed range that is left;
 * a hit whose range is already within that extent stays a hit. */
void markUnsure(Ray& ray, double min_range);

class Rangefinder
{
   public:
	/** Throws std::invalid_argument on bad parameters or an empty floor histogram. */
	Rangefinder(const RangefinderParams& params, const ColourModel& colours);

	const RangefinderParams& params() const { return p_; }
	const OmniCameraModel& camera() const { return camera_; }
	const FreeSpaceClassifier& classifier() const { return classifier_; }
	const PolarScanner& scanner() const { return scanner_; }
	/** true when exposure compensation is asked for but the histogram
	 * records no colour from training to compensate towards. */
	bool compensationMissing() const { return p_.exposure_compensation && !compensate_; }
	/** The floor just beyond the base (ExposureCompensation.h, FloorAdaptation.h). */
	const FloorRing& floorRing() const { return ring_; }

	/** The box of the image process() and FloorAdaptation read: the
	 * scanlines, the floor ring and the exposure check's disc. A scan of an
	 * image decoded only there is the scan of the whole image. */
	PixelBox pixelsRead() const;

	/** One decoded BGR image of the camera's size -> one scan. `adapted`:
	 * classify with it instead of the trained classifier (learnFloor()).
	 * `times`: where to put what each stage took (the benchmark's shares). */
	RangeScan process(const cv::Mat& bgr, const PixelClassifier* adapted = nullptr, StageTimes* times = nullptr) const;

	/** With floor_adaptation: learns the floor ring of the next image, in the
	 * order the images were taken, and returns the classifier to scan it
	 * with (FloorAdaptation.h); without, nothing. The one call that changes
	 * the Rangefinder: process() stays free to run on many threads. */
	std::optional<FreeSpaceClassifier> learnFloor(const cv::Mat& bgr);
	/** learnFloor() then process(): the next image of a live camera or a log. */
	RangeScan processNext(const cv::Mat& bgr);
	bool adaptsToFloor() const { return adaptation_.has_value(); }

	/** Calls `use` with the classifier process() classifies `bgr` through
	 * (`adapted` or the trained one, seen through exposure compensation when
	 * it is on), so that a view of the classification shows what the scan saw. */
	void withClassifierFor(const cv::Mat& bgr, const PixelClassifier* adapted,
						   const std::function<void(const PixelClassifier&)>& use) const;

	/** The scan as an MRPT observation: S rays over 2 pi (S-1)/S, ray i at
	 * scanline i's bearing, valid where status is Hit (and Unsure, with
	 * unsure_rays = obstacle); the intensity channel is each ray's
	 * confidence times kFullConfidence (kFullConfidence: hit or free). */
	mrpt::obs::CObservation2DRangeScan::Ptr toObservation(
		const RangeScan& scan, mrpt::Clock::time_point stamp) const;

   private:
	RangefinderParams p_;
	OmniCameraModel camera_;
	FreeSpaceClassifier classifier_;
	PolarScanner scanner_;
	std::array<double, 3> reference_{};  // the floor's colour around the base in training
	bool compensate_{false};
	FloorRing ring_;
	FloorRing check_disc_;  // from the ring out to max range, every fourth pixel of radius
	std::optional<FloorAdaptation> adaptation_;  // with floor_adaptation
};

}  // namespace omnirange
