#include "omnirange/io/RawlogReader.h"

#include "omnirange/io/OutputRule.h"
#include "omnirange/io/RawlogWriter.h"
#include "omnirange/config/AtomicWrite.h"
#include "omnirange/config/ErrorText.h"
#include "omnirange/config/OptionsTable.h"
#include "omnirange/config/Temporaries.h"


#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>
#include <stdexcept>

namespace omnirange
{
namespace
{
/** The rawlogs this process has read, by path as given (a link switched between two readings is
 * another rawlog under the same name): the rawlog's and its images' identities when first read.
 * A program that reads one again (calibrate's passes) reads the same or fails. */
std::map<std::string, std::pair<std::string, std::string>>& readings()
{
	static std::map<std::string, std::pair<std::string, std::string>> read;
	return read;
}
std::mutex readings_mutex;

std::string asGiven(const std::string& path)
{
	std::error_code ec;
	return std::filesystem::absolute(path, ec).lexically_normal().string();
}
}  // namespace

RawlogReader::RawlogReader(const std::string& path)
	: path_(path), in_(std::make_unique<mrpt::io::CFileGZInputStream>())
{
	requireRegularFile(path, "rawlog");
	// The checks below read the rawlog and its images by name: what they read must be what is opened.
	const std::string rawlog_opened = fileStateOf(path);
	images_ = ImagesAsOpened(path);
	if (!std::filesystem::is_regular_file(path) || !in_->open(path))
	{
		// A report killed between moving its old folder aside and putting the new one in.
		if (const std::string old = halfReplaced(path); !old.empty())
			throw std::runtime_error("cannot open rawlog '" + path + "': a run that was replacing '" +
									 old.substr(0, old.rfind(".old-")) + "' was killed, leaving the old one in '" + old +
									 "' (run that program again)");
		throw std::runtime_error("cannot open rawlog '" + path + "'");
	}
	// A writer killed between moving the old images aside and the new ones in (once in, they are
	// marked pending until their rawlog is: an old folder left beside whole ones is only not removed yet).
	std::error_code ec;
	if (const std::string old = std::filesystem::exists(imagesDirToRead(path), ec) ? "" : halfReplaced(imagesDirToRead(path)); !old.empty())
		throw std::runtime_error("'" + imagesDirToRead(path) + "' may not be the images of rawlog '" + path +
								 "': a run that was replacing them was killed, leaving the old ones in '" + old +
								 "' (run that program again: which folder is this rawlog's cannot be told)");
	// Images moved in before their rawlog, by a run still putting them in place or killed before its rawlog was.
	if (const std::string run = markerValue(imagesDirToRead(path), "pending"); !run.empty())
		throw std::runtime_error("'" + imagesDirToRead(path) + "' may not be the images of rawlog '" + path + "': run " +
								 run + " was putting them in place with their rawlog and had not finished (if it was killed, " +
								 "run that program again)");
	const auto replaced = [&] { return fileStateOf(path) != rawlog_opened; };
	const std::runtime_error replaced_error("rawlog '" + path + "' was replaced as it was opened (a run wrote it again " +
											"meanwhile): read it again");
	// Its content checked once a run: a later pass over the same files need not read it all again.
	const auto reading = std::make_pair(rawlog_opened, images_.identity());
	const bool read_before = [&] {
		const std::lock_guard<std::mutex> g(readings_mutex);
		const auto at = readings().find(asGiven(path));
		return at != readings().end() && at->second == reading;
	}();
	try
	{
		if (!read_before) requireRawlogOfImages(path, imagesDirToRead(path));
	}
	catch (const std::runtime_error&)
	{
		if (replaced()) throw replaced_error;  // not another rawlog put there by hand: a run's, as it was read
		throw;
	}
	if (replaced()) throw replaced_error;
	requireImagesUnchanged();
	{
		const std::lock_guard<std::mutex> g(readings_mutex);
		const auto [at, first] = readings().emplace(asGiven(path), reading);
		// Images gone since: the reading says so itself.
		if (!first && (at->second.first != rawlog_opened ||
					   (!images_.identity().empty() && at->second.second != images_.identity())))
			throw std::runtime_error("rawlog '" + path + "' or its images were written again since this program read " +
									 "them first (a run wrote them meanwhile): run it again");
	}
	mrpt::img::CImage::setImagesPathBase(imagesDirToRead(path));
	temporaries::setActivity("reading rawlog '" + path + "'");
}

RawlogReader::~RawlogReader() = default;

void forgetReadings()
{
	const std::lock_guard<std::mutex> g(readings_mutex);
	readings().clear();
}

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
