#include "omnirange_eval/Figures.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace omnirange::eval
{
cv::Mat differenceHistogram(const std::vector<double>& d, const std::string& title, double range, double bin)
{
	const int nb = static_cast<int>(std::lround(2 * range / bin));
	std::vector<int> counts(nb, 0);
	for (double x : d)
	{
		const int b = static_cast<int>(std::floor((x + range) / bin));
		if (b >= 0 && b < nb) ++counts[b];
	}
	const int W = 800, H = 500, L = 70, R = 20, T = 40, B = 60;
	cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
	const int top = std::max(1, *std::max_element(counts.begin(), counts.end()));
	const double bw = double(W - L - R) / nb;
	for (int b = 0; b < nb; ++b)
	{
		const int h = static_cast<int>(double(H - T - B) * counts[b] / top);
		cv::rectangle(img, cv::Point(int(L + b * bw), H - B - h), cv::Point(int(L + (b + 1) * bw) - 1, H - B),
					  cv::Scalar(180, 110, 40), cv::FILLED);
	}
	const auto text = [&](const std::string& s, int x, int y, double scale = 0.45) {
		cv::putText(img, s, {x, y}, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
	};
	cv::line(img, {L, H - B}, {W - R, H - B}, cv::Scalar(0, 0, 0));
	cv::line(img, {L, T}, {L, H - B}, cv::Scalar(0, 0, 0));
	for (double x = -range; x <= range + 1e-9; x += 0.25)
	{
		const int px = static_cast<int>(L + (x + range) / (2 * range) * (W - L - R));
		cv::line(img, {px, H - B}, {px, H - B + 5}, cv::Scalar(0, 0, 0));
		char s[16];
		std::snprintf(s, sizeof s, "%.2f", x);
		text(s, px - 18, H - B + 22);
	}
	for (int k = 0; k <= 4; ++k)
	{
		const int py = H - B - (H - T - B) * k / 4;
		text(std::to_string(top * k / 4), 5, py + 5);
	}
	text("laser - omnicam [m]", W / 2 - 80, H - 12, 0.55);
	text(title, L, 25, 0.6);
	return img;
}

cv::Mat sideBySide(const std::vector<std::pair<std::string, cv::Mat>>& images)
{
	std::vector<cv::Mat> cols;
	for (const auto& [title, m] : images)
	{
		cv::Mat col(m.rows + 36, m.cols, CV_8UC3, cv::Scalar(255, 255, 255));
		m.copyTo(col(cv::Rect(0, 36, m.cols, m.rows)));
		cv::putText(col, title, {8, 25}, cv::FONT_HERSHEY_SIMPLEX, 0.7, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
		cv::rectangle(col, cv::Rect(0, 0, col.cols, col.rows), cv::Scalar(120, 120, 120));
		cols.push_back(col);
	}
	cv::Mat out;
	cv::hconcat(cols, out);
	return out;
}

}  // namespace omnirange::eval
