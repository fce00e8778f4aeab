#pragma once
// What every fuzz target shares: the parsers under test read files, so the
// input's bytes are written to a file first; a parser's own error (a
// std::exception with a message) is the expected outcome of bad bytes.
// Anything else (a crash, a sanitizer report, a hang, an exception that is
// not a std::exception) is a finding.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace omnirange::fuzz
{
/** The input as a file named NAME in a folder of this process's own; removed
 * when it goes out of scope. */
class FuzzInput
{
   public:
	FuzzInput(const std::uint8_t* data, std::size_t size, const std::string& name)
	{
		static const std::filesystem::path dir = [] {
			auto d = std::filesystem::temp_directory_path() / ("omnirange_fuzz_" + std::to_string(::getpid()));
			std::filesystem::create_directories(d);
			return d;
		}();
		path_ = (dir / name).string();
		std::ofstream(path_, std::ios::binary | std::ios::trunc)
			.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
	}
	~FuzzInput()
	{
		std::error_code ec;
		std::filesystem::remove(path_, ec);
	}
	FuzzInput(const FuzzInput&) = delete;
	FuzzInput& operator=(const FuzzInput&) = delete;

	const std::string& path() const { return path_; }

   private:
	std::string path_;
};

/** Runs `parse`; a std::exception is the parser rejecting the input, fine. */
template <class F>
void expectEitherResultOrError(F&& parse)
{
	try
	{
		parse();
	}
	catch (const std::exception&)
	{
	}
}

}  // namespace omnirange::fuzz
