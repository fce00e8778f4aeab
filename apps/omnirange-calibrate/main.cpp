// omnirange-calibrate: fit the mirror's R (paraboloid) or alpha (first-order
// model) against a laser: for every laser ray, the image radius where the
// omnicam's floor ends at the same bearing, paired with the laser's range.
#include "AppMain.h"
#include "RangefinderIni.h"

#include <omnirange/Accuracy.h>
#include <omnirange/ImageScanPairer.h>
#include <omnirange/ObservationImage.h>
#include <omnirange/RawlogReader.h>

#include <algorithm>
#include <cmath>

using namespace omnirange;

int main(int argc, char** argv)
{
	return app::runApp("omnirange-calibrate", [&] {
		TCLAP::CmdLine cmd("omnirange-calibrate: fit the mirror's R or alpha against a laser (paper §IV-D)", ' ', "0.1");
		TCLAP::ValueArg<std::string> in("i", "input", "rawlog with OMNICAM images and LASER scans", true, "", "RAWLOG", cmd);
		TCLAP::ValueArg<std::string> ini("c", "config", "ini with the rangefinder's parameters (a first guess of R or alpha)", true, "", "INI", cmd);
		TCLAP::ValueArg<std::string> section("s", "section", "ini section", false, "rangefinder", "NAME", cmd);
		TCLAP::ValueArg<std::string> hist("H", "histogram", "histogram file from omnirange-train", true, "", "FILE", cmd);
		TCLAP::ValueArg<std::string> omni("", "omni-label", "label of the images", false, "OMNICAM", "LABEL", cmd);
		TCLAP::ValueArg<std::string> laser("", "laser-label", "label of the laser scans", false, "LASER", "LABEL", cmd);
		TCLAP::ValueArg<int> every("", "every", "use every N-th image/scan pair", false, 5, "N", cmd);
		app::parseArgs(cmd, argc, argv);
		if (every.getValue() < 1) throw std::invalid_argument("--every must be >= 1");

		const RangefinderParams params = app::loadRangefinderIni(ini.getValue(), section.getValue());
		const Rangefinder rf(params, ColourHistogram::load(hist.getValue()));
		RawlogReader reader(in.getValue());
		ImageScanPairer pairer(omni.getValue(), laser.getValue(), 0.1);
		std::vector<RhoRangePair> pairs;
		for (int k = 0; auto obj = reader.next();)
		{
			if (!pairer.add(obj) || k++ % every.getValue() != 0) continue;
			const RangeScan omni_scan = rf.process(decodeImage(*pairer.image(), params.camera));
			const auto obs = rf.toObservation(omni_scan, pairer.image()->timestamp);
			// Hits only; a laser range beyond the current max range cannot have one.
			for (const RangePair& p : pairScans(*pairer.scan(), *obs, 1e9))
				if (p.status != PairStatus::LaserBeyondMaxRange && omni_scan.rays[p.omni_ray].status == RayStatus::Hit)
					pairs.push_back({omni_scan.rays[p.omni_ray].hit_rho, p.laser});
		}
		if (pairs.size() < 10)
			throw std::runtime_error("only " + std::to_string(pairs.size()) + " image/laser ray pairs with a hit in '" +
									 in.getValue() + "': too few to calibrate");
		// Fit, drop the pairs the fit explains worst (misclassified rays), fit again.
		const double h = params.camera.h;
		const auto residual = [&](const CameraParams& cp, const RhoRangePair& p) {
			return std::abs(OmniCameraModel(cp).thetaFromRho(p.rho) - std::atan2(p.range, h));
		};
		CameraParams para = params.camera, first = params.camera;
		para.mirror_model = MirrorModel::Paraboloid;
		first.mirror_model = MirrorModel::FirstOrder;
		para.R = fitR(pairs, h);
		std::vector<double> res;
		for (const auto& p : pairs) res.push_back(residual(para, p));
		std::vector<double> sorted = res;
		std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
		const double cut = 3.0 * std::max(1e-6, sorted[sorted.size() / 2]);
		std::vector<RhoRangePair> kept;
		for (std::size_t i = 0; i < pairs.size(); ++i)
			if (res[i] <= cut) kept.push_back(pairs[i]);
		para.R = fitR(kept, h);
		first.alpha = fitAlpha(kept, h);
		std::printf("pairs: %zu (%zu kept after dropping residuals over 3x the median)\n", pairs.size(), kept.size());
		std::printf("paraboloid:   R = %.2f px      RMS range error %.3f m (ini's R = %.2f: %.3f m)\n", para.R,
					rmsRangeError(OmniCameraModel(para), kept), params.camera.R, rmsRangeError(OmniCameraModel(params.camera), kept));
		std::printf("first order:  alpha = %.2f px/rad   RMS range error %.3f m\n", first.alpha,
					rmsRangeError(OmniCameraModel(first), kept));
		// With the ini's mirror: how far (in image radius) the laser's boundary lies
		// beyond where the omnicam put it; its median suggests boundary_offset.
		const OmniCameraModel current(params.camera);
		std::vector<double> px;
		for (const auto& p : kept) px.push_back(current.rhoFromDistance(p.range) - p.rho);
		std::nth_element(px.begin(), px.begin() + px.size() / 2, px.end());
		std::printf("boundary: the laser's edge lies a median %+.2f px beyond the omnicam's "
					"(suggested boundary_offset = %.2f with the ini's mirror)\n",
					px[px.size() / 2], params.scanner.boundary_offset + px[px.size() / 2]);
		return 0;
	});
}
