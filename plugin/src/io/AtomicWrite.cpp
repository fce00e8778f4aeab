#include "omnirange/io/AtomicWrite.h"

#include <opencv2/imgcodecs.hpp>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace omnirange
{
void writeAtomically(
	const std::string& path, const std::function<void(const std::string&)>& write)
{
	const std::string tmp =
		path + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
	try
	{
		write(tmp);
	}
	catch (...)
	{
		std::remove(tmp.c_str());
		throw;
	}
	if (std::rename(tmp.c_str(), path.c_str()) != 0)
	{
		std::remove(tmp.c_str());
		throw std::runtime_error("cannot rename temporary file to '" + path + "'");
	}
}

void writeFileAtomically(const std::string& path, const std::string& bytes)
{
	writeAtomically(path, [&](const std::string& tmp) {
		std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
		if (!f) throw std::runtime_error("cannot write '" + path + "'");
		f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
		f.close();
		if (!f) throw std::runtime_error("error while writing '" + path + "'");
	});
}

void writeImageAtomically(const std::string& path, const cv::Mat& image)
{
	const auto dot = path.rfind('.');
	std::vector<uchar> buf;
	if (dot == std::string::npos || !cv::imencode(path.substr(dot), image, buf))
		throw std::runtime_error("cannot encode image '" + path + "'");
	writeFileAtomically(path, std::string(buf.begin(), buf.end()));
}

}  // namespace omnirange
