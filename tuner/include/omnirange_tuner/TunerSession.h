#pragma once
// What omnirange-tuner shows and changes, without a window: a rawlog's
// omnicam frames with their laser (and true, where the simulator wrote it)
// scans, the rangefinder's parameters and colour model, one frame scanned
// and compared with its laser, the whole rawlog scored, a histogram trained,
// and the [rangefinder] section saved into the user's ini. The GUI is a thin
// view over this class; the tests drive it directly.

#include <omnirange/core/Rangefinder.h>
#include <omnirange/io/RawlogReader.h>
#include <omnirange/train/LaserComparison.h>
#include <omnirange/train/RawlogTraining.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>

#include <opencv2/core.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace omnirange::tuner
{
struct SessionOptions
{
	std::string rawlog;
	std::string ini;  ///< read for the camera and the parameters; saved into by saveIni()
	std::string section{kRangefinderSection};
	std::string histogram;  ///< empty: train one with train() before scanning
	std::string omni_label{kOmnicamLabel}, laser_label{kLaserLabel}, truth_label{kTruthLabel};
	double max_dt{kDefaultMaxPairingDt};
};

/** One omnicam frame and what was taken with it. */
struct Frame
{
	mrpt::obs::CObservationImage::Ptr image;
	mrpt::obs::CObservation2DRangeScan::Ptr laser;  ///< null if none within max_dt
	mrpt::obs::CObservation2DRangeScan::Ptr truth;  ///< null if the rawlog has none
};

/** One frame scanned with the current parameters. */
struct FrameScan
{
	int index{-1};
	cv::Mat bgr;  ///< the decoded image
	RangeScan scan;
	mrpt::obs::CObservation2DRangeScan::Ptr omni;  ///< the scan as MRPT sees it
	std::vector<RangePair> laser_pairs, truth_pairs;  ///< empty without a laser / truth scan
	double scan_ms{0};  ///< classify + search + filter, this frame
};

/** Mean absolute difference over the compared pairs (paper §IV-B). */
struct Agreement
{
	std::size_t compared{0};
	double mean_abs{0};
	int frames{0};
	int unreadable{0};  ///< frames left out because their image could not be read
};
Agreement agreementOf(const std::vector<RangePair>& pairs);

/** The whole rawlog scored: the agreement over all frames with a laser, and
 * each frame's own mean absolute difference against its laser and its truth
 * (NaN where the frame has none, or its image could not be read), and its
 * share of unsure rays (NaN where its image could not be read). */
struct LogScore : Agreement
{
	std::vector<double> laser_by_frame, truth_by_frame, unsure_by_frame;
};

class TunerSession
{
   public:
	/** Reads the rawlog's frames, the ini and the histogram, and decodes the
	 * first frame that decodes to check it has the camera's size; throws
	 * std::runtime_error naming what is wrong (a missing images folder, a
	 * wrong size, no frame that decodes) before any window opens. */
	explicit TunerSession(SessionOptions options);

	int frames() const { return static_cast<int>(frames_.size()); }
	const Frame& frame(int k) const { return frames_.at(k); }
	const SessionOptions& options() const { return o_; }

	const RangefinderParams& params() const { return params_; }
	/** The parameters the ini held at the start. */
	const RangefinderParams& loaded() const { return loaded_; }
	/** Validates and takes new parameters; throws std::invalid_argument
	 * (the old ones stay) if they are impossible. */
	void setParams(const RangefinderParams& params);
	/** Whether the parameters differ from what the ini held or saveIni() last wrote. */
	bool unsaved() const;
	bool hasColours() const { return rf_ != nullptr; }
	const ColourModel& colours() const { return colours_; }
	const Rangefinder& rangefinder() const;

	/** Frame k's image, decoded (the last one is kept). Throws
	 * std::runtime_error when it cannot be read, and when the images folder
	 * was replaced since the rawlog was read (ImagesAsOpened). */
	const cv::Mat& image(int k);
	/** Scans frame k (0-based) with the current parameters. */
	FrameScan scan(int k);
	/** Every frame scanned and compared with its laser (and truth, where the
	 * rawlog has it); `progress(done, total)`. A frame whose image cannot be
	 * read is counted and left out; an images folder replaced meanwhile throws. */
	LogScore scoreAll(const std::function<void(int, int)>& progress = {});
	/** scoreAll() with the parameters `with` (an A/B against those in force,
	 * which are back in force after it). */
	LogScore scoreWith(const RangefinderParams& with, const std::function<void(int, int)>& progress = {});
	/** Takes new parameters as setParams() does, remembering the ones in force
	 * for undo() (nothing, when every key reads as before). */
	void changeParams(const RangefinderParams& params);
	/** Back to the parameters before the last changeParams(); false if none. */
	bool undo();
	/** Back to the parameters the ini held at the start (undoable). */
	void resetToLoaded();
	/** Trains the colour model on the open rawlog (its laser-labelled pairs)
	 * with the current camera, saves it to `histogram` and uses it. */
	RawlogTrainingResult train(const std::string& histogram, TrainingParams training = {},
							   const std::function<void(std::size_t objects_read)>& progress = {});
	/** Writes every [section] key with its current value into `ini` (the
	 * session's own by default), keeping the file's comments and other sections.
	 * Checks requireSaveAllowed() first: the files may have moved since. */
	void saveIni(const std::string& ini = "");
	/** Throws std::runtime_error, one line, when `ini` may not be saved into:
	 * what is read (the rawlog, the histogram, the bases the ini had when it
	 * was read, through links), not an ini, or an ini gone since it was
	 * first checked or read (moved or removed: a new file would hold none of
	 * its other keys). */
	void requireSaveAllowed(const std::string& ini);

   private:
	void checkImages();
	std::vector<std::string> bases_;  ///< the ini's bases when it was read: never saved into
	/** Each ini saved into, as it was when first checked (at the start, for the -c and --save-to ones). */
	struct SaveTarget
	{
		int keys;              ///< the keys it held (-1: none there)
		std::string leads_to;  ///< the file it named, links resolved
	};
	std::map<std::string, SaveTarget> save_targets_;

	SessionOptions o_;
	std::vector<Frame> frames_;
	RangefinderParams params_;
	RangefinderParams saved_;  ///< what the ini holds
	RangefinderParams loaded_;  ///< what the ini held at the start
	std::vector<RangefinderParams> undo_;  ///< the parameters before each change, latest last
	ColourModel colours_;
	std::unique_ptr<Rangefinder> rf_;
	/** Frames are decoded lazily: one decoded after a run wrote the log again
	 * would be shown and scored under the laser and truth read before. */
	ImagesAsOpened images_;
	int cached_{-1};
	cv::Mat cached_bgr_;
};

}  // namespace omnirange::tuner
