#include "omnirange/io/RawlogWriter.h"

#include "omnirange/config/AtomicWrite.h"
#include "omnirange/io/OutputRule.h"
#include "omnirange/io/RawlogReader.h"
#include "omnirange/io/RawlogScan.h"
#include "omnirange/config/Temporaries.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <opencv2/imgcodecs.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <optional>
#include <set>
#include <fstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace omnirange
{
namespace
{
/** NAME of NAME.rawlog, NAME.rawlog.gz or NAME: the three share NAME_Images. */
std::string rawlogStem(const std::string& file_name)
{
	std::string stem = file_name;
	for (const std::string ext : {".rawlog.gz", ".rawlog"})
		if (stem.size() > ext.size() && stem.compare(stem.size() - ext.size(), ext.size(), ext) == 0)
			return stem.substr(0, stem.size() - ext.size());
	return stem;
}
}  // namespace

std::string imagesDirFor(const std::string& rawlog_path)
{
	const fs::path p(rawlog_path);
	return (p.parent_path() / (rawlogStem(p.filename().string()) + "_Images")).string();
}

std::string imagesDirToRead(const std::string& rawlog_path)
{
	const std::string beside = imagesDirFor(rawlog_path);
	std::error_code ec;
	if (fs::exists(fs::symlink_status(beside, ec)) || !fs::is_symlink(rawlog_path, ec)) return beside;
	return imagesDirFor(fs::weakly_canonical(rawlog_path, ec).string());
}

namespace
{
/** `images` is the link a scan wrote beside `rawlog` to its input's images:
 * a link to a NAME_Images folder, beside a rawlog of ours. Only then may a
 * link be replaced unasked (a user's own link to a folder of theirs is not). */
bool imagesLinkOf(const std::string& rawlog, const std::string& images)
{
	std::error_code ec;
	if (!fs::is_symlink(images, ec)) return false;
	const std::string target = fs::read_symlink(images, ec).lexically_normal().filename().string();
	const std::string suffix = "_Images";
	const bool to_images = target.size() > suffix.size() &&
						   target.compare(target.size() - suffix.size(), suffix.size(), suffix) == 0;
	return to_images && fs::is_regular_file(rawlog, ec) && isOfKind(rawlog, OutputKind::Rawlog);
}
/** NAME_Images serves every rawlog named NAME (NAME.rawlog, NAME.rawlog.gz,
 * NAME): its marker names the one it was written with, and while that one
 * is there, another name does not take its images over. */
void requireImagesOf(const std::string& images, const std::string& rawlog)
{
	std::error_code ec;
	const fs::path dir = fs::path(rawlog).parent_path();
	const std::string mine = fs::path(rawlog).filename().string();
	// Another rawlog here that reads these images (NAME, NAME.rawlog, NAME.rawlog.gz; a link too).
	const std::string stem = rawlogStem(mine);
	for (const auto& other : {stem, stem + ".rawlog", stem + ".rawlog.gz"})
		if (other != mine && fs::exists(fs::symlink_status(dir / other, ec)) &&
			(fs::is_symlink(dir / other, ec) || isOfKind((dir / other).string(), OutputKind::Rawlog)))
			throw std::runtime_error("'" + (dir / other).string() + "' reads '" + images + "' too: '" + rawlog +
									 "' would give it other images (give the output another name)");
	if (fs::is_symlink(images, ec) || !fs::is_directory(images, ec)) return;
	// The rawlog the folder was written with, if it is of this name's stem (a copied folder names another).
	for (const auto& line : markerLines(images))
		if (line.rfind("rawlog ", 0) == 0 && line.substr(7) != mine)
		{
			const fs::path owner = dir / line.substr(7);
			if (imagesDirFor(owner.string()) == images && fs::exists(fs::symlink_status(owner, ec)))
				throw std::runtime_error("'" + images + "' holds the images of '" + owner.string() + "', which '" + rawlog +
										 "' would take over (give the output another name)");
		}
}

/** The output `rawlog` is named as MRPT's programs read its images where they go. */
void requireRawlogName(const std::string& rawlog)
{
	// MRPT's programs read NAME.EXT's images from NAME_Images (the name without its last extension), ours
	// from the name without .rawlog or .rawlog.gz: only NAME.rawlog is read with the same images by both.
	const std::string name = fs::path(outputPath(rawlog)).filename().string(), ext = ".rawlog";
	if (name.find('.') == std::string::npos) return;  // NAME: NAME_Images for both
	if (name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0) return;
	const std::string dot = name.substr(0, name.rfind('.'));
	throw std::runtime_error("the output '" + rawlog + "' is not named NAME.rawlog: MRPT's programs (RawLogViewer, " +
							 "rawlog-edit) would look for its images in '" + dot + "_Images', not in '" +
							 fs::path(imagesDirFor(rawlog)).filename().string() + "' where they go; name it " +
							 rawlogStem(name) + ".rawlog");
}

}  // namespace

void requireRawlogOutputAllowed(const std::string& rawlog, const std::string& program,
								const std::vector<std::string>& inputs, bool force)
{
	requireOutputAllowed(rawlog, OutputKind::Rawlog, "", inputs, force);
	if (!force) requireNotAnothersPart(rawlog, program);
	// The images go beside the file written (through a link, the file it names): both names are read by MRPT.
	const std::string file = replacedFileOf(outputPath(rawlog)), images = imagesDirFor(file);
	requireRawlogName(rawlog);
	if (file != outputPath(rawlog)) requireRawlogName(file);
	// Only a scan writes such a link: another program's output does not replace it unasked.
	requireOutputAllowed(images, OutputKind::Folder, program, inputs,
						 force || (program == kScanProgram && imagesLinkOf(file, images)));
	if (!force) requireImagesOf(images, file);
}

RawlogWriter::RawlogWriter(const std::string& path, const std::string& program, int gz_level)
	: path_(replacedFileOf(path)),
	  owner_(program),  // its NAME_Images folder's marker names the program, as any folder of its
	  tmp_path_(temporaryOf(path_)),
	  images_(imagesDirFor(path_)),  // beside the file written, where a reader of it looks
	  tmp_images_(temporaryOf(images_)),
	  out_(std::make_unique<mrpt::io::CFileGZOutputStream>())
{
	recoverLeftoversOf(path_, OutputKind::Rawlog);  // what killed runs of this output left
	recoverLeftoversOf(images_, OutputKind::Folder, owner_);
	// What is left there is not a temporary of ours to remove.
	requireNothingAt(tmp_path_, "temporary file");
	requireNothingAt(tmp_images_, "images folder");
	temporaries::add(tmp_path_);
	temporaries::add(tmp_images_);
	errno = 0;
	if (!out_->open(tmp_path_, gz_level))
	{
		temporaries::forget(tmp_path_), temporaries::forget(tmp_images_);
		throw std::runtime_error(cannotWrite(path));
	}
}

RawlogWriter::~RawlogWriter()
{
	temporaries::forget(tmp_path_), temporaries::forget(tmp_images_);
	if (committed_) return;
	out_.reset();
	std::error_code ec;
	fs::remove(tmp_path_, ec);
	fs::remove_all(tmp_images_, ec);
}

void RawlogWriter::write(const mrpt::serialization::CSerializable& obj)
{
	try
	{
		errno = 0;
		mrpt::serialization::archiveFrom(*out_) << obj;
	}
	catch (const std::exception&)
	{
		// MRPT's message is a stack trace that does not name the file.
		throw std::runtime_error(cannotWrite(path_, "is the disk full?"));
	}
	++count_;
}

void RawlogWriter::startImages()
{
	if (has_images_) return;
	fs::create_directories(tmp_images_);
	markOutputFolder(tmp_images_, owner_);
	noteInMarker(tmp_images_, "rawlog " + fs::path(path_).filename().string());
	has_images_ = true;
}

mrpt::img::CImage RawlogWriter::externalImageCopy(const std::string& source, const std::string& name,
												  const std::string& checked_state)
{
	startImages();
	listOutputFile(tmp_images_, name);  // before it is written: a killed run's list holds it
	std::error_code ec;
	fs::copy_file(source, fs::path(tmp_images_) / name, fs::copy_options::overwrite_existing, ec);
	// Reading the source was checked when it was decoded: what fails here is the writing (a full disk).
	if (ec)
		throw std::runtime_error("cannot write image '" + (fs::path(images_) / name).string() + "' (copied from '" +
								 source + "'): " + ec.message() + (ec.value() == EIO || ec.value() == EFBIG || ec.value() == ENOSPC
																	   ? " (is the disk full?)"
																	   : ""));
	// After the copy: changed before or while it was copied, what went in is not what was checked.
	if (fileStateOf(source) != checked_state)
		throw std::runtime_error("image '" + source + "' changed after it was checked (a run wrote it again " +
								 "meanwhile): run this again");
	mrpt::img::CImage img;
	img.setExternalStorage(name);
	return img;
}

mrpt::img::CImage RawlogWriter::externalImage(
	const cv::Mat& bgr, const std::string& name, int jpeg_quality)
{
	startImages();
	listOutputFile(tmp_images_, name);  // before it is written: a killed run's list holds it
	const std::string file = (fs::path(tmp_images_) / name).string();
	errno = 0;
	if (!cv::imwrite(file, bgr, {cv::IMWRITE_JPEG_QUALITY, jpeg_quality}))
		throw std::runtime_error(cannotWrite(file, "is the disk full?"));
	mrpt::img::CImage img;
	img.setExternalStorage(name);
	return img;
}

std::size_t RawlogWriter::shareImagesOf(const std::string& existing_dir)
{
	// Images stored inside the rawlog: no folder to share.
	if (std::error_code none; !fs::exists(existing_dir, none)) return 0;
	startImages();
	std::size_t copied = 0;
	// Folders walked through links too, each once, and none that holds this one (a link may lead back up).
	std::error_code ec;
	const std::string root = fs::weakly_canonical(existing_dir, ec).string();
	std::set<std::string> walked;
	const std::function<void(const fs::path&)> share = [&](const fs::path& rel) {
		std::error_code ec;
		for (fs::directory_iterator it(fs::path(existing_dir) / rel, ec), end; !ec && it != end; it.increment(ec))
		{
			const fs::path name = rel / it->path().filename(), to = fs::path(tmp_images_) / name;
			if (name == kOutputMarker) continue;  // that folder's, not this one's
			// A link that leads nowhere (or to itself) is no image: a reader of the output finds it missing, as of the input.
			std::error_code broken;
			const auto status = fs::status(it->path(), broken);
			if (broken) continue;
			if (fs::is_directory(status))
			{
				const std::string at = fs::weakly_canonical(it->path(), broken).string();
				if (!broken && (root + "/").rfind(at + "/", 0) != 0 && walked.insert(at).second &&
					fs::create_directories(to, broken))
					share(name);
				continue;
			}
			listOutputFile(tmp_images_, name.string());  // before it is there: a killed run's list holds it
			// A link to the same bytes; across file systems (or where links are not allowed), a copy.
			if (::linkat(AT_FDCWD, it->path().c_str(), AT_FDCWD, to.c_str(), AT_SYMLINK_FOLLOW) == 0) continue;
			if (fs::copy_file(it->path(), to, broken); broken)
				throw std::runtime_error("cannot put '" + it->path().string() + "' into '" + images_ + "' (" +
										 broken.message() +
										 (broken.value() == ENOSPC || broken.value() == EDQUOT || broken.value() == EIO ||
												  broken.value() == EFBIG
											  ? "; is the disk full?"
											  : "") +
										 ")");
			++copied;
		}
		if (ec)
			throw std::runtime_error("cannot read the images folder '" + (fs::path(existing_dir) / rel).string() + "' (" +
									 ec.message() + ")");
	};
	share("");
	return copied;
}

void RawlogWriter::commit(const std::vector<StagedFile*>& along, const std::function<void()>& with_images)
{
	out_->close();
	// CFileGZOutputStream::close() reports nothing: read the file back, so a
	// flush that failed (a full disk) is found before the file is renamed.
	const std::uint32_t content = requireWholeGzipFile(tmp_path_, path_);
	keepModeOf(path_, tmp_path_);
	syncToDisk(tmp_path_, path_);
	const FolderLock lock(path_);  // another run's renames wait for these
	FileSetCommit files(along);
	if (!has_images_)
	{
		files.put();
		if (with_images) with_images();
		fs::rename(tmp_path_, path_);
		files.finish();
		committed_ = true;
		forgetReadings();
		return;
	}
	// The rule the programs check before they start, checked again here for
	// every writer (a library user need not have called it).
	const bool replace_any = replace_any_ || (owner_ == kScanProgram && imagesLinkOf(path_, images_));
	requireOutputAllowed(images_, OutputKind::Folder, owner_, {}, replace_any);
	if (!replace_any_) requireImagesOf(images_, path_);
	// New images go in marked "pending" until their rawlog is in: a run killed
	// between the two leaves images that every reader refuses, old rawlog or not.
	const std::string pending = "pending " + std::to_string(::getpid());
	listOutputFolder(tmp_images_), noteInMarker(tmp_images_, pending);
	noteInMarker(tmp_images_, "content " + std::to_string(content));  // which rawlog is theirs
	// The old images go aside, the new ones in, then the rawlog; only when
	// all moves succeeded is the old folder removed.
	const bool had_old = fs::is_symlink(images_) || fs::exists(images_);
	const MovedAside old = had_old ? moveAside(images_, replace_any) : MovedAside{};
	bool moved_in = false;
	try
	{
		fs::rename(tmp_images_, images_), moved_in = true;
		files.put();
		if (with_images) with_images();
		fs::rename(tmp_path_, path_);
	}
	catch (const std::exception& e)
	{
		std::error_code back;
		const std::string left = files.undo();
		if (moved_in) fs::remove_all(images_, back);  // ours, just moved in
		if (had_old && !back) fs::rename(old.path, images_, back);
		// What the folder refuses to the commit (made read-only or immutable meanwhile) it may refuse to the undo.
		std::string images_left;
		if (back && had_old)
			images_left = "the old images could not be put back (" + back.message() + "): they are in '" + old.path + "'";
		else if (back)
			images_left = "the new images could not be taken out (" + back.message() + "): remove '" + images_ + "'";
		std::string said = left;
		if (!images_left.empty()) said += (said.empty() ? "" : "; ") + images_left;
		throw std::runtime_error("cannot move '" + path_ + "' and its images into place (" + e.what() + "); " +
								 (said.empty() ? "the old ones are as they were" : said));
	}
	files.finish();
	committed_ = true;
	forgetReadings();
	bool unnoted = false;
	std::string why;
	try
	{
		unnoted = unnoteInMarker(images_, pending);
	}
	catch (const std::exception& e)
	{
		why = std::string(" (") + e.what() + ")";
	}
	if (!unnoted)
		throw std::runtime_error("'" + path_ + "' is in place, but its images '" + images_ + "' were moved or replaced " +
								 "while the run put them there" + why +
								 (had_old ? "; the old ones are in '" + old.path + "'" : "") + ": run it again");
	if (had_old) removeReplaced(old);
}

}  // namespace omnirange
