#include "omnirange/io/RawlogScan.h"

#include <mrpt/obs/CObservation2DRangeScan.h>

#include "omnirange/core/ScanFusion.h"
#include <omnirange/config/Output.h>
#include "omnirange/core/Threads.h"
#include "omnirange/io/ObservationImage.h"
#include "omnirange/io/RawlogProcessor.h"
#include "omnirange/io/RawlogWriter.h"

#include <mrpt/obs/CSensoryFrame.h>

#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <array>
#include <exception>
#include <filesystem>
#include <optional>

namespace omnirange
{
namespace
{
/** Objects read but not yet written, with the images among them and their scans. */
struct Batch
{
	std::vector<mrpt::serialization::CSerializable::Ptr> objects;
	std::vector<std::size_t> after;  // per image: the index of the object that holds it
	std::vector<mrpt::obs::CObservationImage::Ptr> images;
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;  // one per image
	// Fusing only, per image: the laser scan taken with it (or none) and the
	// object after which the FUSED scan goes (the later of the two).
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> lasers, fused;
	std::vector<std::size_t> fused_after;
	std::vector<std::array<int, 5>> statuses;  // per image: its rays by RayStatus (Hit, NoHit, TooClose, Outlier, Unsure)
	std::vector<char> grey;  // per image: its three channels equal
	std::vector<std::exception_ptr> errors;
};

/** Whether the BGR `image` has three equal channels in `region` (the whole
 * image if empty): a grey camera's, or a log converted to grey. */
bool isGrey(const cv::Mat& whole, const PixelBox& region)
{
	const cv::Mat image = region.empty() ? whole
										 : whole(cv::Rect(region.left, region.top, region.right - region.left + 1,
														  region.bottom - region.top + 1));
	cv::Mat channels[3];
	cv::split(image, channels);
	return cv::countNonZero(channels[0] != channels[1]) == 0 && cv::countNonZero(channels[1] != channels[2]) == 0;
}

/** Decodes (and scans) the batch's images in parallel. With floor
 * adaptation, the floor is learned from each decoded image in file order
 * first, and each image is scanned with what was learned up to and including
 * it: the result does not depend on the number of threads. */
void processBatch(Batch& b, Rangefinder& rf, const PixelBox& region, std::vector<cv::Mat>& decoded, bool decode_only)
{
	const int n = static_cast<int>(b.images.size());
	b.scans.assign(n, nullptr);
	b.fused.assign(n, nullptr);
	b.lasers.resize(n), b.fused_after.resize(n);
	b.statuses.assign(n, {0, 0, 0, 0, 0});
	b.errors.assign(n, nullptr);
	b.grey.assign(n, 0);
	decoded.resize(std::max<std::size_t>(decoded.size(), n));  // the last batch's buffers, reused
	const auto& cam = rf.params().camera;
	const auto scan = [&](int k, const PixelClassifier* classifier) {
		const RangeScan scan = rf.process(decoded[k], classifier);
		for (const Ray& ray : scan.rays) ++b.statuses[k][static_cast<std::size_t>(ray.status)];
		b.scans[k] = rf.toObservation(scan, b.images[k]->timestamp);
		if (b.lasers[k]) b.fused[k] = fuseScans(*b.scans[k], *b.lasers[k]);
	};
	cv::parallel_for_(cv::Range(0, n), [&](const cv::Range& r) {
		for (int k = r.start; k < r.end; ++k) try
			{
				decodeImage(*b.images[k], cam, region, decoded[k]);
				if (decode_only) continue;
				b.grey[k] = isGrey(decoded[k], region);
				if (!rf.adaptsToFloor()) scan(k, nullptr);
			}
			catch (...)
			{
				b.errors[k] = std::current_exception();
			}
	});
	if (decode_only || !rf.adaptsToFloor()) return;
	std::vector<std::optional<FreeSpaceClassifier>> classifiers(n);
	for (int k = 0; k < n; ++k)
		if (!b.errors[k]) classifiers[k] = rf.learnFloor(decoded[k]);
	cv::parallel_for_(cv::Range(0, n), [&](const cv::Range& r) {
		for (int k = r.start; k < r.end; ++k) try
			{
				if (!b.errors[k]) scan(k, &*classifiers[k]);
			}
			catch (...)
			{
				b.errors[k] = std::current_exception();
			}
	});
}

/** The message of a stored exception. */
std::string messageOf(const std::exception_ptr& error)
{
	try
	{
		std::rethrow_exception(error);
	}
	catch (const std::exception& e)
	{
		return e.what();
	}
	catch (...)
	{
		return "an error without a message";
	}
}

/** Writes the batch's objects with each image's scan: inside the image's
 * sensory frame, or right after the image in the observations-only format. */
void writeBatch(const Batch& b, RawlogWriter* writer, bool skip_bad, RawlogScanSummary& sum)
{
	std::size_t k = 0, f = 0;
	for (std::size_t i = 0; i < b.objects.size(); ++i)
	{
		std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
		for (; k < b.images.size() && b.after[k] == i; ++k)
		{
			if (b.errors[k])
			{
				if (!skip_bad) std::rethrow_exception(b.errors[k]);
				++sum.skipped;
				sum.skipped_reasons.push_back(messageOf(b.errors[k]));
				continue;
			}
			++sum.images;
			if (!b.scans[k]) continue;  // decode only
			const auto& n = b.statuses[k];
			const auto of = [&](RayStatus s) { return static_cast<std::size_t>(n[static_cast<std::size_t>(s)]); };
			sum.hits += of(RayStatus::Hit), sum.no_hit += of(RayStatus::NoHit);
			sum.too_close += of(RayStatus::TooClose), sum.outliers += of(RayStatus::Outlier);
			sum.unsure += of(RayStatus::Unsure);
			sum.rays += b.scans[k]->getScanSize();
			sum.grey_images += b.grey[k];
			scans.push_back(b.scans[k]);
		}
		// A fused scan's laser is never read before its image's: f never passes k.
		for (; f < k && (!b.lasers[f] || b.fused_after[f] <= i); ++f)
			if (b.fused[f]) scans.push_back(b.fused[f]), ++sum.fused;
		if (!writer) continue;
		if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(b.objects[i]))
		{
			for (const auto& scan : scans) sf->insert(scan);
			writer->write(*sf);
			continue;
		}
		writer->write(*b.objects[i]);
		for (const auto& scan : scans) writer->write(*scan);
	}
}

/** Cuts off `b`'s tail, from the object holding its last image on, with that
 * object's images and any image whose laser scan came in the tail: a batch of
 * its own, read on, for the last image's laser scan may still come (a sensory
 * frame may hold it with the next image). */
Batch tailFrom(Batch& b)
{
	Batch tail;
	std::size_t first = b.images.size() - 1, cut = b.after[first];
	while (first > 0 && (b.after[first - 1] >= cut || (b.lasers[first - 1] && b.fused_after[first - 1] >= cut)))
		--first, cut = std::min(cut, b.after[first]);
	tail.objects.assign(b.objects.begin() + static_cast<std::ptrdiff_t>(cut), b.objects.end());
	for (std::size_t k = first; k < b.images.size(); ++k)
	{
		tail.after.push_back(b.after[k] - cut), tail.images.push_back(b.images[k]);
		tail.lasers.push_back(b.lasers[k]), tail.fused_after.push_back(b.lasers[k] ? b.fused_after[k] - cut : 0);
	}
	b.objects.resize(cut), b.after.resize(first), b.images.resize(first);
	b.lasers.resize(first), b.fused_after.resize(first);
	return tail;
}
}  // namespace

RawlogScanSummary scanRawlog(Rangefinder rf, const RawlogScanOptions& o, Progress* progress)
{
	if (o.threads < 1 || o.threads > 256) throw std::invalid_argument("threads must be within [1, 256]");
	if (!o.decode_only) requireRawlogOutputAllowed(o.output, kScanProgram, {o.input, imagesDirToRead(o.input)}, o.force);
	useThreads(o.threads);

	RawlogProcessor loop(o.input);
	std::optional<RawlogWriter> writer;
	RawlogScanSummary sum;
	if (!o.decode_only)
	{
		writer.emplace(o.output, kScanProgram, o.force);
		// Taken now, while the reader holds the input open: if they are replaced before it ends, it fails.
		sum.images_copied = writer->shareImagesOf(imagesDirToRead(o.input));
	}
	const std::size_t batch_images = 8 * static_cast<std::size_t>(o.threads);
	Batch b;
	const bool fusing = !o.fuse_with.empty() && !o.decode_only;
	const PixelBox region = o.whole_images ? PixelBox{} : rf.pixelsRead();
	std::vector<cv::Mat> decoded;
	// A batch ends only between objects: a sensory frame may hold several images. When fusing,
	// an image still without its laser scan goes on into the next batch with what follows it.
	const auto flush = [&](bool at_end) {
		Batch tail = fusing && !at_end && !b.images.empty() && !b.lasers.back() ? tailFrom(b) : Batch{};
		processBatch(b, rf, region, decoded, o.decode_only);
		writeBatch(b, writer ? &*writer : nullptr, o.skip_bad_images, sum);
		b = std::move(tail);
	};
	loop.onObject([&](const mrpt::serialization::CSerializable::Ptr& obj) {
		if (b.images.size() >= batch_images) flush(false);
		b.objects.push_back(obj);
	});
	loop.on<mrpt::obs::CObservationImage>(o.omni_label, [&](const mrpt::obs::CObservationImage::Ptr& image) {
		b.after.push_back(b.objects.size() - 1);
		b.images.push_back(image);
		b.lasers.emplace_back(), b.fused_after.emplace_back();
	});
	if (fusing)
	{
		loop.onPair<mrpt::obs::CObservationImage, mrpt::obs::CObservation2DRangeScan>(
			o.omni_label, o.fuse_with, o.max_dt, [&](const auto& image, const auto& laser) {
				// The image is the batch's last: a later one would have replaced it in the pairer.
				if (b.images.empty() || b.images.back() != image) return;
				b.lasers.back() = laser, b.fused_after.back() = b.objects.size() - 1;
			});
		loop.on<mrpt::obs::CObservation2DRangeScan>(kFusedLabel, [&](const auto&) {
			throw std::runtime_error("'" + o.input + "' already holds " + std::string(kFusedLabel) +
									 " scans: fuse the rawlog they were made from");
		});
	}
	// Scans of this label already in the input would sit beside the new ones, two per frame.
	loop.on<mrpt::obs::CObservation2DRangeScan>(rf.params().sensor_label, [&](const auto&) {
		throw std::runtime_error("'" + o.input + "' already holds " + rf.params().sensor_label +
								 " scans: scan the rawlog they were made from, or give the new ones another sensor_label");
	});
	loop.run(progress);
	flush(true);
	loop.requireImagesUnchanged();  // the last batch was decoded after the end of the file
	if (sum.images == 0 && sum.skipped > 0)
		throw std::runtime_error("every " + o.omni_label + " image in '" + o.input + "' was bad; the first: " +
								 sum.skipped_reasons.front());
	if (sum.images == 0)
		throw std::runtime_error("no " + o.omni_label + " image in '" + o.input + "' (" + loop.describeLabels() + ")");
	if (fusing && sum.fused == 0)
		throw std::runtime_error("nothing to fuse: " + loop.describeNoPair());
	if (writer)
	{
		writer->commit();
		sum.objects = writer->objectsWritten();
	}
	return sum;
}

}  // namespace omnirange
