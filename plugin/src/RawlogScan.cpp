#include "omnirange/RawlogScan.h"

#include "omnirange/ObservationImage.h"
#include "omnirange/RawlogReader.h"
#include "omnirange/RawlogWriter.h"

#include <opencv2/core/utility.hpp>

#include <exception>
#include <filesystem>
#include <optional>

namespace omnirange
{
namespace
{
/** Objects read but not yet written, with the scans of their images. */
struct Batch
{
	std::vector<mrpt::serialization::CSerializable::Ptr> objects;
	std::vector<std::size_t> images;  // indices into objects
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;  // one per image
	std::vector<std::exception_ptr> errors;
};

/** Decodes (and scans) the batch's images in parallel. */
void processBatch(Batch& b, const Rangefinder& rf, bool decode_only)
{
	b.scans.assign(b.images.size(), nullptr);
	b.errors.assign(b.images.size(), nullptr);
	const auto& cam = rf.params().camera;
	cv::parallel_for_(cv::Range(0, static_cast<int>(b.images.size())), [&](const cv::Range& r) {
		for (int k = r.start; k < r.end; ++k) try
			{
				const auto& img = static_cast<const mrpt::obs::CObservationImage&>(*b.objects[b.images[k]]);
				const cv::Mat bgr = decodeImage(img, cam);
				if (!decode_only) b.scans[k] = rf.toObservation(rf.process(bgr), img.timestamp);
			}
			catch (...)
			{
				b.errors[k] = std::current_exception();
			}
	});
}
}  // namespace

RawlogScanSummary scanRawlog(const Rangefinder& rf, const RawlogScanOptions& o,
							 const std::function<void(std::size_t)>& progress)
{
	namespace fs = std::filesystem;
	if (o.threads < 1) throw std::invalid_argument("threads must be >= 1");
	if (!o.decode_only && fs::exists(o.output) && fs::exists(o.input) && fs::equivalent(o.input, o.output))
		throw std::invalid_argument("the output must not be the input rawlog");
	cv::setNumThreads(o.threads);

	RawlogReader reader(o.input);
	std::optional<RawlogWriter> writer;
	if (!o.decode_only)
	{
		writer.emplace(o.output);
		writer->linkImagesTo(imagesDirFor(o.input));
	}
	const std::size_t batch_images = 8 * static_cast<std::size_t>(o.threads);
	RawlogScanSummary sum;
	Batch b;
	const auto flush = [&] {
		processBatch(b, rf, o.decode_only);
		for (std::size_t k = 0, i = 0; i < b.objects.size(); ++i)
		{
			if (writer) writer->write(*b.objects[i]);
			if (k >= b.images.size() || b.images[k] != i) continue;
			if (b.errors[k]) std::rethrow_exception(b.errors[k]);
			if (writer)
			{
				const auto& scan = *b.scans[k];
				writer->write(scan);
				for (std::size_t r = 0; r < scan.getScanSize(); ++r) sum.hits += scan.getScanRangeValidity(r);
				sum.rays += scan.getScanSize();
			}
			++k, ++sum.images;
		}
		b = Batch{};
		if (progress) progress(sum.images);
	};
	while (auto obj = reader.next())
	{
		auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obj);
		if (img && img->sensorLabel == o.omni_label) b.images.push_back(b.objects.size());
		b.objects.push_back(std::move(obj));
		if (b.images.size() >= batch_images) flush();
	}
	flush();
	if (sum.images == 0) throw std::runtime_error("no " + o.omni_label + " image in '" + o.input + "'");
	if (writer)
	{
		writer->commit();
		sum.objects = writer->objectsWritten();
	}
	return sum;
}

}  // namespace omnirange
