// omnirange-scan: rawlog + histogram + ini -> the same rawlog with an
// OMNISCAN CObservation2DRangeScan right after every OMNICAM image.
#include "AppMain.h"
#include "Progress.h"
#include "RangefinderIni.h"

#include <omnirange/ObservationImage.h>
#include <omnirange/RawlogReader.h>
#include <omnirange/RawlogWriter.h>

#include <opencv2/core/utility.hpp>

#include <exception>
#include <filesystem>

using namespace omnirange;

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

/** Decodes and scans the batch's images on `threads` cores. */
void scanBatch(Batch& b, const Rangefinder& rf, const std::string& ini)
{
	b.scans.assign(b.images.size(), nullptr);
	b.errors.assign(b.images.size(), nullptr);
	const auto& cam = rf.params().camera;
	cv::parallel_for_(cv::Range(0, static_cast<int>(b.images.size())), [&](const cv::Range& r) {
		for (int k = r.start; k < r.end; ++k) try
			{
				const auto& img = static_cast<const mrpt::obs::CObservationImage&>(*b.objects[b.images[k]]);
				const cv::Mat bgr = decodeImage(img);
				if (bgr.cols != cam.image_width || bgr.rows != cam.image_height)
					throw std::runtime_error(
						"image '" + img.image.getExternalStorageFile() + "' is " + std::to_string(bgr.cols) + "x" +
						std::to_string(bgr.rows) + " but " + ini + " says " + std::to_string(cam.image_width) + "x" +
						std::to_string(cam.image_height));
				b.scans[k] = rf.toObservation(rf.process(bgr), img.timestamp);
			}
			catch (...)
			{
				b.errors[k] = std::current_exception();
			}
	});
}
}  // namespace

int main(int argc, char** argv)
{
	return app::runApp("omnirange-scan", [&] {
		TCLAP::CmdLine cmd("omnirange-scan: add an omnicam range scan after every omnicam image of a rawlog", ' ', "0.1");
		TCLAP::ValueArg<std::string> in("i", "input", "rawlog with OMNICAM images", true, "", "RAWLOG", cmd);
		TCLAP::ValueArg<std::string> out("o", "output", "rawlog to write (all input observations plus the scans)", true, "", "RAWLOG", cmd);
		TCLAP::ValueArg<std::string> ini("c", "config", "ini with the rangefinder's parameters (docs/parameters.md)", true, "", "INI", cmd);
		TCLAP::ValueArg<std::string> section("s", "section", "ini section", false, "rangefinder", "NAME", cmd);
		TCLAP::ValueArg<std::string> hist("H", "histogram", "histogram file from omnirange-train", true, "", "FILE", cmd);
		TCLAP::ValueArg<std::string> omni("", "omni-label", "label of the images to scan", false, "OMNICAM", "LABEL", cmd);
		TCLAP::ValueArg<int> threads("j", "threads", "threads decoding and scanning images", false, 2, "N", cmd);
		TCLAP::SwitchArg quiet("q", "quiet", "no progress or summary", cmd);
		app::parseArgs(cmd, argc, argv);
		if (threads.getValue() < 1) throw std::invalid_argument("--threads must be >= 1");
		namespace fs = std::filesystem;
		if (fs::exists(out.getValue()) && fs::exists(in.getValue()) && fs::equivalent(in.getValue(), out.getValue()))
			throw std::invalid_argument("the output must not be the input rawlog");

		const RangefinderParams params = app::loadRangefinderIni(ini.getValue(), section.getValue());
		const Rangefinder rf(params, ColourHistogram::load(hist.getValue()));
		cv::setNumThreads(threads.getValue());

		RawlogReader reader(in.getValue());
		RawlogWriter writer(out.getValue());
		writer.linkImagesTo(imagesDirFor(in.getValue()));
		const std::size_t batch_images = 8 * static_cast<std::size_t>(threads.getValue());
		std::size_t scanned = 0, hits = 0, rays = 0;
		Batch b;
		const auto flush = [&] {
			scanBatch(b, rf, ini.getValue());
			for (std::size_t k = 0, i = 0; i < b.objects.size(); ++i)
			{
				writer.write(*b.objects[i]);
				if (k < b.images.size() && b.images[k] == i)
				{
					if (b.errors[k]) std::rethrow_exception(b.errors[k]);
					writer.write(*b.scans[k]);
					for (std::size_t r = 0; r < b.scans[k]->getScanSize(); ++r) hits += b.scans[k]->getScanRangeValidity(r);
					rays += b.scans[k]->getScanSize();
					++k, ++scanned;
				}
			}
			b = Batch{};
			if (!quiet.getValue()) app::showProgress("images scanned", static_cast<int>(scanned), static_cast<int>(scanned));
		};
		while (auto obj = reader.next())
		{
			auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obj);
			if (img && img->sensorLabel == omni.getValue()) b.images.push_back(b.objects.size());
			b.objects.push_back(std::move(obj));
			if (b.images.size() >= batch_images) flush();
		}
		flush();
		if (scanned == 0)
			throw std::runtime_error("no " + omni.getValue() + " image in '" + in.getValue() + "'");
		writer.commit();
		if (!quiet.getValue())
			std::printf("%zu images scanned, %.1f %% of rays hit, %zu objects -> %s\n", scanned,
						100.0 * hits / std::max<std::size_t>(1, rays), writer.objectsWritten(), out.getValue().c_str());
		return 0;
	});
}
