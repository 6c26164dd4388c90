// The binary form of case files, `gjk-cases-msgpack/1` (docs/case-files.md, "Binary case files"):
// the same cases as a gjk-cases/1 file, bit for bit, as a MessagePack stream of a header and
// blocks of columns, for traces of millions of queries. Read by the readers of cases.hpp, which
// recognise it by its first byte; written here.
#pragma once

#include "inputs/cases.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace gjkval
{

inline constexpr const char* kBinaryCaseFormat = "gjk-cases-msgpack/1";

// Limits of the binary reader, beside the per-case ones of cases.hpp (kMaxCaseNameBytes,
// kMaxShapePoints, kMaxCommentBytes, kMaxComments): what one block can cost in memory.
inline constexpr std::size_t kMaxBlockCases = 65'536;                // entries of a block
inline constexpr std::size_t kMaxBlockBytes = std::size_t(96) << 20; // one block's MessagePack
// The writer closes a block at kWriterBlockCases cases or kWriterBlockPoints points of one shape
// column, whichever comes first: a block stays far below kMaxBlockBytes (a single case of two
// kMaxShapePoints shapes is 32 MB).
inline constexpr std::size_t kWriterBlockCases = 4096;
inline constexpr std::size_t kWriterBlockPoints = std::size_t(1) << 20;

// Which form a case file's first byte says it is in: a MessagePack map header (0x80-0x8F, 0xDE,
// 0xDF) is the binary form's header; no JSON text starts with one of those bytes (each is a UTF-8
// continuation or a lead byte of a non-ASCII character, none of them JSON's whitespace or value).
bool isBinaryCaseFileStart(unsigned char firstByte);
// True when `path` is a regular file whose first byte is that of the binary form. A pipe is not
// looked at (reading its first byte would take it from the JSON reader): binary case files are
// read from regular files.
bool isBinaryCaseFile(const std::string& path);

// The readers of cases.hpp for the binary form: a header that is not gjk-cases-msgpack/1, a block
// whose columns do not agree (lengths, counts), a file cut short or not MessagePack throws
// InputError naming the file, the block, its cases and the field; a case with an invalid value
// (NaN, a negative radius, a bad name, ...) is kept as a rejected entry with the message the JSON
// reader gives for the same field.
// `sourceName`: how messages and labels name the file (a pipe's copy is read from another path).
CaseFileSummary streamBinaryCaseFile(const std::string& path, const std::string& sourceName,
                                     const std::function<void(CaseEntry&&)>& consume);
CaseFile readBinaryCaseFile(const std::string& path);
CaseFile parseBinaryCaseFile(std::string_view bytes, const std::string& sourceName);

// Writes the binary form as a stream: the header when constructed, then cases in blocks; finish()
// writes the last block. `sink` receives the bytes in order (it may throw: nothing is kept).
class BinaryCaseWriter
{
  public:
    using Sink = std::function<void(std::string_view)>;
    BinaryCaseWriter(Sink sink, const std::vector<std::string>& comments);
    void add(const Case& c);
    void finish();
    std::size_t cases() const { return written_ + block_.size(); }

  private:
    void flush();
    Sink sink_;
    std::vector<Case> block_;
    std::size_t blockPoints_ = 0;
    std::size_t written_ = 0;
};

// The whole binary form of a list of cases, in memory (tests, small files).
std::string binaryCaseFileBytes(const std::vector<std::string>& comments,
                                const std::vector<Case>& cases);

// The format names `generate --format` and gjk2d.write_cases take: "json" (gjk-cases/1, the
// default) and "msgpack" (gjk-cases-msgpack/1).
enum class CaseFileFormat
{
    Json,
    Msgpack,
};
inline constexpr const char* kCaseFileFormatNames[] = {"json", "msgpack"};
// The format a name says, or InputError listing the names.
CaseFileFormat caseFileFormatNamed(const std::string& name, const std::string& option);

} // namespace gjkval
