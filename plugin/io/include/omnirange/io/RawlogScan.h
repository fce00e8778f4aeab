#pragma once
// omnirange-scan's job as a library function: stream a rawlog, add a range
// scan right after every omnicam image, write the result atomically. Images
// are decoded and scanned on several threads in batches, so memory does not
// grow with the rawlog's length.

#include <omnirange/core/Rangefinder.h>
#include <omnirange/config/SensorLabels.h>
#include <omnirange/io/ObservationPairer.h>

#include <string>
#include <vector>

namespace omnirange
{
/** The program whose outputs (a rawlog, its images) these are (config/Output.h). */
inline constexpr char kScanProgram[] = "omnirange-scan";

class Progress;

struct RawlogScanOptions
{
	std::string input;  ///< rawlog with the images
	std::string output;  ///< rawlog to write (not the input)
	std::string omni_label{kOmnicamLabel};  ///< label of the images to scan
	int threads{2};  ///< threads decoding and scanning
	/** Read and decode only: no scan, nothing written (the baseline the
	 * benchmark compares against). */
	bool decode_only{false};
	/** Decode each image whole, not only the box the scan reads
	 * (Rangefinder::pixelsRead): the same scans, slower (to time and check it). */
	bool whole_images{false};
	/** A missing, cut or undecodable image is skipped (no scan for it, counted
	 * in the summary and named in `skipped_names`) instead of stopping the run. */
	bool skip_bad_images{false};
	/** Replace an output (or NAME_Images) no program of ours wrote (never an input; config/Output.h). */
	bool force{false};
	/** Label of a laser on the same robot: each scan is also fused with the
	 * laser scan taken within max_dt of its image into a FUSED scan
	 * (core/ScanFusion.h), written after the later of the two. Empty: none. */
	std::string fuse_with;
	double max_dt{kDefaultMaxPairingDt};  ///< [s] largest time between an image and the laser scan fused with it
};

struct RawlogScanSummary
{
	std::size_t images{0};  ///< images scanned (or decoded)
	std::size_t objects{0};  ///< objects written
	std::size_t rays{0}, hits{0};  ///< rays produced, and of them hits
	/** Of the rays, those without a hit: free to the max range (no_hit), ended
	 * at once or inside min range (too_close), rejected by the outlier filter. */
	std::size_t no_hit{0}, too_close{0}, outliers{0};
	std::size_t unsure{0};  ///< of the rays, those free only up to their confident extent (valid with unsure_rays = obstacle)
	std::size_t skipped{0};  ///< bad images skipped (skip_bad_images only)
	std::size_t fused{0};  ///< FUSED scans written (fuse_with only; an image without a laser scan has none)
	std::size_t images_copied{0};  ///< the input's image files copied, not hard-linked (another file system)
	std::size_t grey_images{0};  ///< of the images scanned, those whose three channels are equal (a grey camera's)
	std::vector<std::string> skipped_reasons;  ///< why, one line per skipped image
};

/** In the observations-only format each scan is written right after its
 * image; in the actions/sensory-frames format it goes into the image's frame,
 * so the output keeps the input's format. Throws std::runtime_error naming
 * the file or image on any bad input; the output then does not exist. `progress` counts the objects read.
 * `rangefinder` is a copy: with floor_adaptation each log starts from what training saw. */
RawlogScanSummary scanRawlog(Rangefinder rangefinder, const RawlogScanOptions& options, Progress* progress = nullptr);

}  // namespace omnirange
