#include "omnirange/io/RawlogScan.h"

#include "omnirange/io/AtomicWrite.h"
#include "omnirange/io/ObservationImage.h"
#include "omnirange/io/RawlogProcessor.h"
#include "omnirange/io/RawlogWriter.h"

#include <opencv2/core/utility.hpp>

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
				const cv::Mat bgr = decodeImage(*b.images[k], cam);
				if (!decode_only) b.scans[k] = rf.toObservation(rf.process(bgr), b.images[k]->timestamp);
			}
			catch (...)
			{
				b.errors[k] = std::current_exception();
			}
	});
}

/** Writes the batch's objects, each image's scan right after the object that holds it. */
void writeBatch(const Batch& b, RawlogWriter* writer, RawlogScanSummary& sum)
{
	std::size_t k = 0;
	for (std::size_t i = 0; i < b.objects.size(); ++i)
	{
		if (writer) writer->write(*b.objects[i]);
		for (; k < b.images.size() && b.after[k] == i; ++k)
		{
			if (b.errors[k]) std::rethrow_exception(b.errors[k]);
			++sum.images;
			if (!writer) continue;
			const auto& scan = *b.scans[k];
			writer->write(scan);
			for (std::size_t r = 0; r < scan.getScanSize(); ++r) sum.hits += scan.getScanRangeValidity(r);
			sum.rays += scan.getScanSize();
		}
	}
}
}  // namespace

RawlogScanSummary scanRawlog(const Rangefinder& rf, const RawlogScanOptions& o, Progress* progress)
{
	if (o.threads < 1 || o.threads > 256) throw std::invalid_argument("threads must be within [1, 256]");
	if (!o.decode_only) requireOutputsAreNotInputs({o.output}, {o.input});
	cv::setNumThreads(o.threads);

	RawlogProcessor loop(o.input);
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
		writeBatch(b, writer ? &*writer : nullptr, sum);
		b = Batch{};
	};
	loop.onObject([&](const mrpt::serialization::CSerializable::Ptr& obj) { b.objects.push_back(obj); });
	loop.on<mrpt::obs::CObservationImage>(o.omni_label, [&](const mrpt::obs::CObservationImage::Ptr& image) {
		b.after.push_back(b.objects.size() - 1);
		b.images.push_back(image);
		if (b.images.size() >= batch_images) flush();
	});
	loop.run(progress);
	flush();
	if (sum.images == 0)
		throw std::runtime_error("no " + o.omni_label + " image in '" + o.input + "' (" + loop.describeLabels() + ")");
	if (writer)
	{
		writer->commit();
		sum.objects = writer->objectsWritten();
	}
	return sum;
}

}  // namespace omnirange
