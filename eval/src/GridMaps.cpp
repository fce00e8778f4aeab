#include "omnirange_eval/GridMaps.h"

#include <omnirange/config/Output.h>
#include <omnirange/io/RawlogProcessor.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/serialization/CArchive.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc.hpp>

#include <cerrno>
#include <cmath>

namespace omnirange::eval
{
namespace
{
using Grid = mrpt::maps::COccupancyGridMap2D;

/** 255 where getCell() (P(free)) is below `below`; row 0 is the grid's y = 0 row. */
cv::Mat mask(const Grid& g, float below)
{
	cv::Mat m(static_cast<int>(g.getSizeY()), static_cast<int>(g.getSizeX()), CV_8UC1);
	for (int y = 0; y < m.rows; ++y)
		for (int x = 0; x < m.cols; ++x) m.at<std::uint8_t>(y, x) = g.getCell(x, y) < below ? 255 : 0;
	return m;
}

/** Distance [cells] from every cell to the nearest non-zero cell of `m`. */
cv::Mat distanceTo(const cv::Mat& m)
{
	cv::Mat inv, d;
	cv::bitwise_not(m, inv);
	cv::distanceTransform(inv, d, cv::DIST_L2, cv::DIST_MASK_PRECISE);
	return d;
}
}  // namespace

Grid resampledLike(const Grid& g, const Grid& like)
{
	Grid out = like;
	for (unsigned y = 0; y < like.getSizeY(); ++y)
		for (unsigned x = 0; x < like.getSizeX(); ++x)
		{
			const int gx = g.x2idx(like.idx2x(x)), gy = g.y2idx(like.idx2y(y));
			const bool inside = gx >= 0 && gy >= 0 && gx < int(g.getSizeX()) && gy < int(g.getSizeY());
			out.setCell(x, y, inside ? g.getCell(gx, gy) : 0.5f);
		}
	return out;
}

Grid emptyLike(const Grid& truth, bool invalid_is_free)
{
	Grid g = truth;  // the very same extent and cells
	g.fill(0.5f);
	g.insertionOptions.maxDistanceInsertion = 20.0f;
	g.insertionOptions.considerInvalidRangesAsFreeSpace = invalid_is_free;
	return g;
}

mrpt::maps::CSimpleMap simplemapWithGroundTruth(const std::string& rawlog, const std::string& label,
												const std::vector<StampedPose>& truth)
{
	using mrpt::obs::CObservation2DRangeScan;
	mrpt::maps::CSimpleMap sm;
	RawlogProcessor loop(rawlog);
	loop.on<CObservation2DRangeScan>(label, [&](const CObservation2DRangeScan::Ptr& scan) {
		auto sf = mrpt::obs::CSensoryFrame::Create();
		sf->insert(scan);
		auto pose = mrpt::poses::CPose3DPDFGaussian::Create();
		pose->mean = mrpt::poses::CPose3D(poseAt(truth, mrpt::Clock::toDouble(scan->timestamp)));
		sm.insert(pose, sf);
	});
	loop.run();
	if (sm.empty()) throw std::runtime_error("no " + label + " scan in '" + rawlog + "' (" + loop.describeLabels() + ")");
	return sm;
}

void saveSimplemap(const mrpt::maps::CSimpleMap& sm, const std::string& file)
{
	OutputSet set;
	set.write({file, OutputKind::Text}, [&](const std::string& tmp) {  // no program: staged and committed, not checked
		{
			mrpt::io::CFileGZOutputStream f;
			errno = 0;
			if (!f.open(tmp)) throw std::runtime_error(cannotWrite(file));
			mrpt::serialization::archiveFrom(f) << sm;
		}
		requireWholeGzipFile(tmp, file);  // the stream reports no failed write (a full disk)
	});
	set.commit();
}

Grid mapFromSimplemap(const mrpt::maps::CSimpleMap& sm, const mrpt::poses::CPose2D& alignment, const Grid& like,
					  bool invalid_is_free)
{
	Grid g = emptyLike(like, invalid_is_free);
	for (std::size_t i = 0; i < sm.size(); ++i)
	{
		const auto [pdf, sf] = sm.get(i);
		if (!pdf || !sf) continue;
		const mrpt::poses::CPose3D pose(alignment + mrpt::poses::CPose2D(pdf->getMeanVal()));
		for (const auto& obs : *sf) g.insertObservation(*obs, pose);
	}
	return resampledLike(g, like);
}

cv::Mat paperStyle(const Grid& g)
{
	cv::Mat img(static_cast<int>(g.getSizeY()), static_cast<int>(g.getSizeX()), CV_8UC3);
	for (int y = 0; y < img.rows; ++y)
		for (int x = 0; x < img.cols; ++x)
		{
			const float p = g.getCell(x, y);  // P(free)
			cv::Vec3b c{240, 228, 214};  // unknown: pale blue
			if (p < 0.4f) c = {0, 0, 0};
			else if (p > 0.8f) c = {165, 165, 165};  // well explored free
			else if (p > 0.55f) c = {255, 255, 255};  // less explored free
			img.at<cv::Vec3b>(img.rows - 1 - y, x) = c;  // north up
		}
	return img;
}

MapMetrics compareWithTruth(const Grid& built, const Grid& truth, double tolerance,
							const std::vector<StampedPose>& path, double reach)
{
	const cv::Mat b = mask(built, 0.4f), t = mask(truth, 0.5f);
	// The true walls' surface: occupied cells beside a free one.
	cv::Mat eroded, surface;
	cv::erode(t, eroded, cv::getStructuringElement(cv::MORPH_CROSS, {3, 3}));
	cv::subtract(t, eroded, surface);
	// Only the surface a sensor on the path could have seen counts in the recall.
	cv::Mat near = cv::Mat::zeros(t.size(), CV_8UC1);
	const double res = truth.getResolution();
	for (const auto& p : path)
		cv::circle(near, {truth.x2idx(p.pose.x()), truth.y2idx(p.pose.y())}, static_cast<int>(reach / res),
				   cv::Scalar(255), cv::FILLED);
	cv::bitwise_and(surface, near, surface);

	const cv::Mat to_truth = distanceTo(t), to_built = distanceTo(b);
	const double tol = tolerance / res;
	MapMetrics m;
	std::size_t good = 0, seen = 0, found = 0;
	for (int y = 0; y < b.rows; ++y)
		for (int x = 0; x < b.cols; ++x)
		{
			if (b.at<std::uint8_t>(y, x))
			{
				++m.occupied;
				good += to_truth.at<float>(y, x) <= tol;
			}
			if (surface.at<std::uint8_t>(y, x))
			{
				++seen;
				found += to_built.at<float>(y, x) <= tol;
			}
		}
	m.precision = m.occupied ? double(good) / m.occupied : 0;
	m.recall = seen ? double(found) / seen : 0;
	cv::Mat skeleton;
	cv::ximgproc::thinning(b, skeleton);
	const int line = cv::countNonZero(skeleton);
	m.thickness = line ? res * double(m.occupied) / line : 0;
	return m;
}

double occupiedLengthAt(const Grid& g, double x, double y, double w, double d, double margin)
{
	int occ = 0;
	for (int cy = g.y2idx(y - d / 2 - margin); cy <= g.y2idx(y + d / 2 + margin); ++cy)
		for (int cx = g.x2idx(x - w / 2 - margin); cx <= g.x2idx(x + w / 2 + margin); ++cx)
			if (cx >= 0 && cy >= 0 && cx < int(g.getSizeX()) && cy < int(g.getSizeY()) && g.getCell(cx, cy) < 0.4f)
				++occ;
	return occ * g.getResolution();
}

}  // namespace omnirange::eval
