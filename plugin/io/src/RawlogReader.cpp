#include "omnirange/io/RawlogReader.h"

#include <omnirange/config/Output.h>
#include "omnirange/config/ErrorText.h"
#include "omnirange/config/OptionsTable.h"
#include "omnirange/config/Activity.h"


#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>
#include <stdexcept>

namespace omnirange
{
RawlogReader::RawlogReader(const std::string& path)
	: path_(path), in_(std::make_unique<mrpt::io::CFileGZInputStream>())
{
	requireRegularFile(path, "rawlog");
	// The checks below read the rawlog and its images by name: what they read must be what is opened.
	const std::string rawlog_opened = fileStateOf(path);
	images_ = ImagesAsOpened(path);
	if (!std::filesystem::is_regular_file(path) || !in_->open(path))
		throw std::runtime_error("cannot open rawlog '" + path + "'");
	if (fileStateOf(path) != rawlog_opened)
		throw std::runtime_error("rawlog '" + path + "' was replaced as it was opened (a run wrote it again meanwhile): " +
								 "read it again");
	requireImagesUnchanged();
	mrpt::img::CImage::setImagesPathBase(imagesDirToRead(path));
	activity::set("reading rawlog '" + path + "'");
}

RawlogReader::~RawlogReader() = default;

ImagesAsOpened::ImagesAsOpened(std::string rawlog)
	: rawlog_(std::move(rawlog)), identity_(fileStateOf(imagesDirToRead(rawlog_)))
{
}

void ImagesAsOpened::require() const
{
	if (fileStateOf(imagesDirToRead(rawlog_)) != identity_)
		throw std::runtime_error("the images of rawlog '" + rawlog_ + "' were replaced after it was opened (a run " +
								 "wrote it again meanwhile): open it again");
}



void RawlogReader::requireTimeGoesOn(const mrpt::serialization::CSerializable::Ptr& obj)
{
	std::vector<mrpt::Clock::time_point> times;
	if (const auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) times.push_back(o->timestamp);
	else if (const auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
		for (const auto& o : *sf) times.push_back(o->timestamp);
	for (const auto t : times)
	{
		if (t == INVALID_TIMESTAMP) continue;
		const double seconds = mrpt::Clock::toDouble(t);
		if (latest_ > 0 && seconds < latest_ - kMaxTimeBack)
			throw std::runtime_error("rawlog '" + path_ + "': object " + std::to_string(count_) + " is at " +
									 formatDouble(seconds) + " s, " + formatDouble(std::round((latest_ - seconds) * 1000) / 1000) +
									 " s before one read earlier (two rawlogs joined, or a clock set back?)");
		latest_ = std::max(latest_, seconds);
	}
}

mrpt::serialization::CSerializable::Ptr RawlogReader::next()
{
	const auto before = in_->getPosition();
	const auto fail = [&](const std::string& why) {
		return std::runtime_error(
			"rawlog '" + path_ + "' is truncated or corrupt after " + std::to_string(count_) +
			" objects (" + why + ")");
	};
	mrpt::serialization::CSerializable::Ptr obj;
	try
	{
		obj = mrpt::serialization::archiveFrom(*in_).ReadObject();
	}
	catch (const mrpt::serialization::CExceptionEOF&)
	{
		// Nothing at all read: the file ended between two objects.
		if (in_->getPosition() == before)
		{
			requireImagesUnchanged();
			return nullptr;
		}
		throw fail("it ends inside an object");
	}
	catch (const std::bad_alloc&)
	{
		// MRPT sizes a string or vector from the file before reading it.
		throw fail("a length in it asks for more memory than there is");
	}
	catch (const std::exception& e)
	{
		const std::string what = e.what();
		if (what.find("EOF") != std::string::npos) throw fail("it ends inside an object");
		const std::string said = mrptMessages(what);
		throw fail(oneLine(said.empty() ? what : said));
	}
	if (!obj) throw fail("a null object");
	++count_;
	requireTimeGoesOn(obj);
	return obj;
}


}  // namespace omnirange
