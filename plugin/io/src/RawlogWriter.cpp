#include "omnirange/io/RawlogWriter.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <opencv2/imgcodecs.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <set>
#include <stdexcept>

namespace fs = std::filesystem;

namespace omnirange
{
namespace
{
/** The file a rawlog output writes: through a link, the file it names (its images go beside that). */
std::string fileWritten(const std::string& rawlog) { return writtenThrough(outputPath(rawlog)); }

/** NAME_Images serves every rawlog named NAME (NAME.rawlog, NAME.rawlog.gz,
 * NAME): while another of them is there, this one does not take its images over. */
void requireImagesOf(const std::string& images, const std::string& rawlog)
{
	std::error_code ec;
	const fs::path dir = fs::path(rawlog).parent_path();
	const std::string mine = fs::path(rawlog).filename().string(), folder = fs::path(images).filename().string();
	const std::string stem = folder.substr(0, folder.size() - std::string("_Images").size());
	for (const auto& other : {stem, stem + ".rawlog", stem + ".rawlog.gz"})
		if (other != mine && fs::exists(fs::symlink_status(dir / other, ec)) &&
			(fs::is_symlink(dir / other, ec) || isOfKind((dir / other).string(), OutputKind::Rawlog)))
			throw std::runtime_error("'" + (dir / other).string() + "' reads '" + images + "' too: '" + rawlog +
									 "' would give it other images (give the output another name)");
}

/** The output `rawlog` is named as MRPT's programs read its images where they go. */
void requireRawlogName(const std::string& rawlog)
{
	// MRPT's programs read NAME.EXT's images from NAME_Images (the name without its last extension), ours
	// from the name without .rawlog or .rawlog.gz: only NAME.rawlog is read with the same images by both.
	const std::string name = fs::path(outputPath(rawlog)).filename().string(), ext = ".rawlog";
	if (name.find('.') == std::string::npos) return;  // NAME: NAME_Images for both
	if (name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0) return;
	const std::string images = fs::path(imagesDirFor(rawlog)).filename().string();
	throw std::runtime_error("the output '" + rawlog + "' is not named NAME.rawlog: MRPT's programs (RawLogViewer, " +
							 "rawlog-edit) would look for its images in '" + name.substr(0, name.rfind('.')) +
							 "_Images', not in '" + images + "' where they go; name it " +
							 images.substr(0, images.size() - 7) + ".rawlog");
}

/** What a write that failed with `ec` may add: a full disk's errors say so. */
std::string diskFullHint(const std::error_code& ec)
{
	const int e = ec.value();
	return e == ENOSPC || e == EDQUOT || e == EIO || e == EFBIG ? " (is the disk full?)" : "";
}

}  // namespace

void requireRawlogOutputAllowed(const std::string& rawlog, const std::string& program,
								const std::vector<std::string>& inputs, bool force)
{
	const std::string file = fileWritten(rawlog), images = imagesDirFor(file);
	requireOutputsAllowed({{rawlog, OutputKind::Rawlog}, {images, OutputKind::Folder}}, program, inputs, force);
	requireRawlogName(rawlog);
	if (file != outputPath(rawlog)) requireRawlogName(file);
	requireImagesOf(images, file);  // even with --force: that other rawlog is not replaced, it would read wrong images
}

RawlogWriter::RawlogWriter(const std::string& path, const std::string& program, bool force)
	: set_(program, {}, force), path_(fileWritten(path)), out_(std::make_unique<mrpt::io::CFileGZOutputStream>())
{
	// The images first: commit() puts folders in before the file that names them.
	tmp_images_ = set_.stage({imagesDirFor(path_), OutputKind::Folder});
	tmp_path_ = set_.stage({path_, OutputKind::Rawlog});
	errno = 0;
	if (!out_->open(tmp_path_, 1)) throw std::runtime_error(cannotWrite(path));
}

RawlogWriter::~RawlogWriter() = default;

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
	if (!has_images_) fs::create_directories(tmp_images_);
	has_images_ = true;
}

mrpt::img::CImage RawlogWriter::externalImageCopy(const std::string& source, const std::string& name,
												  const std::string& checked_state)
{
	startImages();
	std::error_code ec;
	fs::copy_file(source, fs::path(tmp_images_) / name, fs::copy_options::overwrite_existing, ec);
	// Reading the source was checked when it was decoded: what fails here is the writing (a full disk).
	if (ec)
		throw std::runtime_error("cannot write image '" + (fs::path(imagesDirFor(path_)) / name).string() + "' (copied from '" +
								 source + "'): " + ec.message() + diskFullHint(ec));
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
			if (name == kOutputMarker) continue;  // that folder's, not this one's (commit() writes its own)
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
			// A link to the same bytes; across file systems (or where links are not allowed), a copy.
			if (::linkat(AT_FDCWD, it->path().c_str(), AT_FDCWD, to.c_str(), AT_SYMLINK_FOLLOW) == 0) continue;
			if (fs::copy_file(it->path(), to, broken); broken)
				throw std::runtime_error("cannot put '" + it->path().string() + "' into '" + imagesDirFor(path_) + "': " +
										 broken.message() + diskFullHint(broken));
			++copied;
		}
		if (ec)
			throw std::runtime_error("cannot read the images folder '" + (fs::path(existing_dir) / rel).string() + "' (" +
									 ec.message() + ")");
	};
	share("");
	return copied;
}

void RawlogWriter::commit()
{
	out_->close();
	// CFileGZOutputStream::close() reports nothing: read the file back, so a
	// flush that failed (a full disk) is found before the file goes in.
	requireWholeGzipFile(tmp_path_, path_);
	set_.commit();
}

}  // namespace omnirange
