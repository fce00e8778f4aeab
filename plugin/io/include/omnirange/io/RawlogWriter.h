#pragma once
// Writes an observations-only, gzip-compressed MRPT rawlog and its folder of
// external images (NAME_Images/ beside NAME.rawlog) as one OutputSet:
// commit() puts the images in, then the rawlog that names them.

#include <omnirange/config/Output.h>

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
/** The guarantee (Output.h) for a rawlog `program` is to write and its
 * NAME_Images; both are named so that MRPT's programs find the images, and
 * no other rawlog of that NAME reads them. Throws naming the path, before any work. */
void requireRawlogOutputAllowed(const std::string& rawlog, const std::string& program,
								const std::vector<std::string>& inputs, bool force);

class RawlogWriter
{
   public:
	/** A rawlog `program` writes (its images folder is marked with its name);
	 * `force`: the user's --force (Output.h). */
	RawlogWriter(const std::string& path, const std::string& program, bool force = false);
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
	/** The set the rawlog goes in with: files that belong with it (a
	 * simulation's true map) are staged there too. */
	OutputSet& outputs() { return set_; }
	/** Finishes the rawlog and puts it, its images and what else was staged
	 * in place as one (OutputSet::commit()). */
	void commit();

	std::size_t objectsWritten() const { return count_; }

   private:
	void startImages();

	OutputSet set_;
	std::string path_, tmp_path_, tmp_images_;
	std::unique_ptr<mrpt::io::CFileGZOutputStream> out_;
	bool has_images_{false};
	std::size_t count_{0};
};

}  // namespace omnirange
