// The driver a fuzz target gets when libFuzzer is not there (a GCC build):
// it runs the target on every file of a seed corpus, then on a number of
// mutations of them (bit flips, byte edits, cut and repeated ranges, splices
// of two inputs, and numbers swapped for edge values: the mutations that
// found the ini and world bugs by hand). Deterministic for a given seed, so
// a failure can be replayed. With a sanitizer build it is a short fuzz run.
//
//   fuzz_world [--mutations N] [--seed S] [--max-len BYTES] [--slow-ms MS --save DIR] CORPUS...
//
// --keep-last FILE writes each input to FILE before running it: after a
// crash, FILE holds the input that caused it.
// --save DIR keeps every input that took longer than --slow-ms (default 1000)
// in DIR, to be replayed alone (pass the file as the corpus).

#include "FuzzInput.h"

#include <omnirange/io/MemoryLimit.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iostream>
#include <chrono>
#include <random>
#include <string>
#include <vector>


namespace
{
using Bytes = std::string;

const std::vector<std::string> kEdgeNumbers = {
	"0", "-1", "1e300", "-1e300", "nan", "inf", "-inf", "2147483647", "2147483648", "-2147483649",
	"99999999999999999999", "1e-320", "0x10", "1,5", "1.5.2", "", "1e9", "65536", "4294967296"};

void runOne(const Bytes& b)
{
	LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(b.data()), b.size());
}

/** Replaces one run of digits (with its sign, point and exponent) by an edge value. */
bool swapNumber(Bytes& b, std::mt19937_64& rng)
{
	std::vector<std::size_t> starts;
	for (std::size_t i = 0; i < b.size(); ++i)
		if (std::isdigit(static_cast<unsigned char>(b[i])) &&
			(i == 0 || !std::isdigit(static_cast<unsigned char>(b[i - 1]))))
			starts.push_back(i);
	if (starts.empty()) return false;
	std::size_t s = starts[rng() % starts.size()];
	if (s > 0 && b[s - 1] == '-') --s;
	std::size_t e = s + 1;
	while (e < b.size() && (std::isalnum(static_cast<unsigned char>(b[e])) || b[e] == '.' || b[e] == '-' || b[e] == '+'))
		++e;
	b.replace(s, e - s, kEdgeNumbers[rng() % kEdgeNumbers.size()]);
	return true;
}

Bytes mutate(const std::vector<Bytes>& corpus, std::mt19937_64& rng, std::size_t max_len)
{
	Bytes b = corpus[rng() % corpus.size()];
	const int edits = 1 + static_cast<int>(rng() % 4);
	for (int n = 0; n < edits; ++n)
	{
		const auto pos = [&] { return b.empty() ? std::size_t{0} : static_cast<std::size_t>(rng() % b.size()); };
		switch (rng() % 8)
		{
			case 0:  // flip a bit
				if (!b.empty()) b[pos()] ^= static_cast<char>(1u << (rng() % 8));
				break;
			case 1:  // a random or edge byte
			{
				static const char edge[] = {0, '\xff', '\x7f', '\x80', '\n', '=', '[', ']', '#', ' ', '-', '.', 'e'};
				if (!b.empty()) b[pos()] = (rng() % 2) ? static_cast<char>(rng()) : edge[rng() % sizeof edge];
				break;
			}
			case 2:  // insert a byte
				b.insert(b.begin() + static_cast<std::ptrdiff_t>(pos()), static_cast<char>(rng()));
				break;
			case 3:  // cut a range (a truncated file when it reaches the end)
				if (!b.empty())
				{
					const std::size_t p = pos();
					b.erase(p, 1 + rng() % std::max<std::size_t>(1, b.size() - p));
				}
				break;
			case 4:  // repeat a range
				if (!b.empty())
				{
					const std::size_t p = pos(), len = 1 + rng() % std::min<std::size_t>(64, b.size() - p);
					b.insert(p, b.substr(p, len));
				}
				break;
			case 5:  // splice: this one's head, another's tail
			{
				const Bytes& other = corpus[rng() % corpus.size()];
				const std::size_t p = pos();
				b = b.substr(0, p) + other.substr(std::min(other.size(), p));
				break;
			}
			default:  // an edge number where a number was
				if (!swapNumber(b, rng) && !b.empty()) b[pos()] = static_cast<char>(rng());
				break;
		}
	}
	if (b.size() > max_len) b.resize(max_len);
	return b;
}

Bytes readFile(const std::filesystem::path& p)
{
	std::ifstream in(p, std::ios::binary);
	return Bytes(std::istreambuf_iterator<char>(in), {});
}
}  // namespace

int main(int argc, char** argv)
{
	long mutations = 0;
	unsigned long long seed = 1;
	std::size_t max_len = 1 << 20;
	double slow_ms = 1000;
	std::string save_dir, keep_last;
	std::vector<Bytes> corpus;
	for (int i = 1; i < argc; ++i)
	{
		const std::string a = argv[i];
		if ((a == "--mutations" || a == "--seed" || a == "--max-len" || a == "--slow-ms" || a == "--save" ||
			 a == "--keep-last") &&
			i + 1 < argc)
		{
			const std::string v = argv[++i];
			if (a == "--mutations") mutations = std::stol(v);
			else if (a == "--seed") seed = std::stoull(v);
			else if (a == "--max-len") max_len = std::stoul(v);
			else if (a == "--slow-ms") slow_ms = std::stod(v);
			else if (a == "--keep-last") keep_last = v;
			else save_dir = v;
			continue;
		}
		const std::filesystem::path p(a);
		if (std::filesystem::is_directory(p))
		{
			std::vector<std::filesystem::path> files;
			for (const auto& e : std::filesystem::directory_iterator(p))
				if (e.is_regular_file()) files.push_back(e.path());
			std::sort(files.begin(), files.end());
			for (const auto& f : files) corpus.push_back(readFile(f));
		}
		else if (std::filesystem::is_regular_file(p))
			corpus.push_back(readFile(p));
		else
		{
			std::cerr << argv[0] << ": no such corpus file or folder '" << a << "'\n";
			return 2;
		}
	}
	if (corpus.empty())
	{
		std::cerr << "usage: " << argv[0] << " [--mutations N] [--seed S] [--max-len BYTES] CORPUS...\n";
		return 2;
	}
	// As in the apps: memory that grows element by element (a deque sized
	// from a corrupt length) ends in bad_alloc, not in the OOM killer.
	omnirange::capAddressSpaceAtHalfTheMemory();
	long slow = 0;
	const auto timed = [&](const Bytes& b) {
		if (!keep_last.empty()) std::ofstream(keep_last, std::ios::binary | std::ios::trunc) << b;
		const auto t0 = std::chrono::steady_clock::now();
		runOne(b);
		const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
		if (ms < slow_ms) return;
		++slow;
		std::cout << "slow input: " << ms << " ms\n";
		if (!save_dir.empty())
			std::ofstream(save_dir + "/slow-" + std::to_string(slow), std::ios::binary) << b;
	};
	for (const auto& b : corpus) timed(b);
	std::mt19937_64 rng(seed);
	for (long n = 0; n < mutations; ++n) timed(mutate(corpus, rng, max_len));
	std::cout << argv[0] << ": " << corpus.size() << " seeds and " << mutations << " mutations (seed " << seed
			  << ") ran without a crash\n";
	return 0;
}
