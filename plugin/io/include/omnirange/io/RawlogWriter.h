#pragma once
// Writes an observations-only, gzip-compressed MRPT rawlog and its folder of
// external images (NAME_Images/ beside NAME.rawlog) under temporary names;
// commit() renames both into place. Destroyed without commit(), it removes
// them, so a failed run leaves nothing that looks whole.

#include <omnirange/config/AtomicWrite.h>

#include <mrpt/img/CImage.h>
#include <mrpt/serialization/CSerializable.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mrpt::io
{
class CFileGZOutputStream;
}

namespace omnirange
{
/** NAME_Images beside NAME.rawlog (the folder MRPT's programs look in). */
std::string imagesDirFor(const std::string& rawlog_path);
/** The images folder a reader of `rawlog_path` uses: imagesDirFor() it, or,
 * when that is missing and the rawlog is a link, the folder beside the file
 * the link leads to (where a writer through the link put the images). */
std::string imagesDirToRead(const std::string& rawlog_path);

/** The output rule (OutputRule.h) for a rawlog `program` is to write and
 * its NAME_Images: the rawlog may replace only a rawlog, the folder only
 * images the same program wrote (or a link beside a rawlog); neither may be,
 * hold or sit in an input. Throws std::runtime_error naming the path, before
 * any work. */
void requireRawlogOutputAllowed(const std::string& rawlog, const std::string& program,
								const std::vector<std::string>& inputs, bool force);

class RawlogWriter
{
   public:
	/** A rawlog `program` writes (its images folder is marked with its name). */
	RawlogWriter(const std::string& path, const std::string& program, int gz_level = 1);
	~RawlogWriter();
	RawlogWriter(const RawlogWriter&) = delete;
	RawlogWriter& operator=(const RawlogWriter&) = delete;

	void write(const mrpt::serialization::CSerializable& obj);
	/** Saves `bgr` as `file_name` (".jpg" or ".png") in the images folder and
	 * returns a CImage stored externally under that name. */
	mrpt::img::CImage externalImage(
		const cv::Mat& bgr, const std::string& file_name, int jpeg_quality = 90);
	/** Copies the image file `source` byte for byte (a camera's JPEG stays
	 * the camera's) as `file_name` into the images folder and returns a
	 * CImage stored externally under that name. `checked_state`: the
	 * source's fileStateOf() when it was checked; a source changed since
	 * (written again meanwhile) throws rather than be copied unchecked. */
	mrpt::img::CImage externalImageCopy(const std::string& source, const std::string& file_name,
										const std::string& checked_state);
	/** Puts every file of an existing images folder into this rawlog's, each
	 * a hard link (a copy across file systems): a rawlog that adds
	 * observations to another (a scan) keeps the images it was made from,
	 * whatever becomes of the other's (none, when there is no such folder).
	 * Returns how many were copied. */
	std::size_t shareImagesOf(const std::string& existing_dir);
	/** Let commit() replace a NAME_Images folder that no rawlog writer of
	 * ours made (the user's --force; the output rule, OutputRule.h). */
	void replaceAnyImagesFolder() { replace_any_ = true; }
	/** Finishes the rawlog and moves it (and its images, if any) into place,
	 * replacing what a rawlog writer of ours wrote there before. If a step
	 * fails, the old rawlog and images are left as they were. Throws
	 * std::runtime_error naming a NAME_Images folder that is not ours.
	 * `along`: files that belong with this rawlog (a simulation's true map),
	 * put in after the images and before the rawlog as one set
	 * (FileSetCommit), and taken out again if the rawlog cannot go in.
	 * `with_images` is called at that point too (a test looks there). */
	void commit(const std::vector<StagedFile*>& along = {}, const std::function<void()>& with_images = {});

	std::size_t objectsWritten() const { return count_; }

   private:
	void startImages();

	std::string path_, owner_, tmp_path_, images_, tmp_images_;
	std::unique_ptr<mrpt::io::CFileGZOutputStream> out_;
	bool has_images_{false}, committed_{false}, replace_any_{false};
	std::size_t count_{0};
};

}  // namespace omnirange
