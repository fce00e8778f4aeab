#pragma once
// Streams an MRPT rawlog (observations-only or actions/sensory-frames,
// gzip or plain) one object at a time, so memory does not grow with its
// length. Unlike MRPT's own readers, which stop silently where a rawlog is
// truncated or holds a class MRPT does not know, it throws, naming the file
// and how many objects were read.

#include <mrpt/serialization/CSerializable.h>

#include <memory>
#include <string>

namespace mrpt::io
{
class CFileGZInputStream;
}

namespace omnirange
{
/** A rawlog's images folder as a reader opened it (fileStateOf(), through
 * links; none if it had none). */
class ImagesAsOpened
{
   public:
	ImagesAsOpened() = default;
	explicit ImagesAsOpened(std::string rawlog);

	/** Throws std::runtime_error when the folder is no longer the one opened
	 * with: another run wrote the rawlog again, and an image decoded now would
	 * be of other scenes than the observations read with it. */
	void require() const;
	const std::string& identity() const { return identity_; }

   private:
	std::string rawlog_;
	std::string identity_;
};

class RawlogReader
{
   public:
	/** Opens `path` and points CImage's external-image folder at
	 * NAME_Images beside it. Throws std::runtime_error if it cannot, and
	 * when this run read it before and it or its images were written again
	 * since (a program that reads a rawlog in several passes reads one). */
	explicit RawlogReader(const std::string& path);
	~RawlogReader();

	/** The next object, or nullptr at a clean end of file (the images
	 * folder still the one opened with, else it throws). Throws
	 * std::runtime_error on a truncated or corrupt file, an unknown class,
	 * or an observation more than kMaxTimeBack before the latest one (two
	 * rawlogs joined, or a clock set back: every pairing by time would be wrong). */
	mrpt::serialization::CSerializable::Ptr next();

	/** ImagesAsOpened::require(): next() checks it at the end of the file, a
	 * reader that decodes images after that again. */
	void requireImagesUnchanged() const { images_.require(); }
	/** For images decoded long after the reader is gone (the tuner's). */
	const ImagesAsOpened& imagesAsOpened() const { return images_; }

	std::size_t objectsRead() const { return count_; }
	const std::string& path() const { return path_; }

   private:
	void requireTimeGoesOn(const mrpt::serialization::CSerializable::Ptr& obj);

	std::string path_;
	std::unique_ptr<mrpt::io::CFileGZInputStream> in_;
	std::size_t count_{0};
	double latest_{0};  ///< [s] the latest observation's time so far (0: none yet)
	/** At the end it must be the same, or another run wrote the rawlog again
	 * meanwhile and part of what was read is of other images. */
	ImagesAsOpened images_;
};

/** [s] How far an observation may come before the latest one: sensors'
 * threads write a little out of order, a log joined to another jumps back. */
inline constexpr double kMaxTimeBack = 1.0;

}  // namespace omnirange
