// gjk-cases-msgpack/1: case files as MessagePack (Debian's libmsgpack-cxx-dev, header only). A
// header map, then blocks of up to kMaxBlockCases cases stored by column; each number column is
// a MessagePack bin of little-endian IEEE doubles (or uint32 counts), so that a block is read with
// a copy per column and written from NumPy arrays as they are. docs/case-files.md, "Binary case
// files", is the reference; docs/speed.md, "Case files", says why this format.
#include "inputs/case_binary.hpp"
#include "inputs/case_fields.hpp"

#define MSGPACK_NO_BOOST
#include <msgpack.hpp>

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace gjkval
{
namespace fs = std::filesystem;
namespace
{
// Little-endian on every host (the cross-platform check runs big-endian s390x).
std::uint64_t toLittle(std::uint64_t v)
{
    if constexpr (std::endian::native == std::endian::big)
    {
        std::uint64_t r = 0;
        for (int i = 0; i < 8; ++i)
            r = (r << 8) | ((v >> (8 * i)) & 0xFF);
        return r;
    }
    return v;
}

std::uint32_t toLittle32(std::uint32_t v)
{
    if constexpr (std::endian::native == std::endian::big)
        return (v >> 24) | ((v >> 8) & 0xFF00) | ((v << 8) & 0xFF0000) | (v << 24);
    return v;
}

// ---- Writing ------------------------------------------------------------------------------

struct StringStream
{
    std::string bytes;
    void write(const char* p, std::size_t n) { bytes.append(p, n); }
};
using Packer = msgpack::packer<StringStream>;

void packStr(Packer& pk, std::string_view s)
{
    pk.pack_str(std::uint32_t(s.size()));
    pk.pack_str_body(s.data(), std::uint32_t(s.size()));
}

void packDoubles(Packer& pk, const std::vector<double>& v)
{
    std::string raw(v.size() * 8, '\0');
    for (std::size_t i = 0; i < v.size(); ++i)
    {
        const std::uint64_t b = toLittle(std::bit_cast<std::uint64_t>(v[i]));
        std::memcpy(raw.data() + 8 * i, &b, 8);
    }
    pk.pack_bin(std::uint32_t(raw.size()));
    pk.pack_bin_body(raw.data(), std::uint32_t(raw.size()));
}

// One shape column of a block: counts, points, radius, p, q.
void packShapes(Packer& pk, const std::vector<Case>& block, ShapeIn Case::*shape)
{
    std::string counts(block.size() * 4, '\0');
    std::vector<double> points, radius, p, q;
    for (std::size_t i = 0; i < block.size(); ++i)
    {
        const ShapeIn& s = block[i].*shape;
        const std::uint32_t n = toLittle32(std::uint32_t(s.points.size()));
        std::memcpy(counts.data() + 4 * i, &n, 4);
        for (const auto& pt : s.points)
            points.push_back(pt[0]), points.push_back(pt[1]);
        radius.push_back(s.radius);
        p.push_back(s.px), p.push_back(s.py);
        q.push_back(s.c), q.push_back(s.s);
    }
    pk.pack_map(5);
    packStr(pk, "counts");
    pk.pack_bin(std::uint32_t(counts.size()));
    pk.pack_bin_body(counts.data(), std::uint32_t(counts.size()));
    packStr(pk, "points");
    packDoubles(pk, points);
    packStr(pk, "radius");
    packDoubles(pk, radius);
    packStr(pk, "p");
    packDoubles(pk, p);
    packStr(pk, "q");
    packDoubles(pk, q);
}

std::string blockBytes(const std::vector<Case>& block)
{
    bool source = false, comment = false;
    for (const auto& c : block)
        source = source || !c.source.empty(), comment = comment || !c.comment.empty();
    StringStream out;
    Packer pk(out);
    pk.pack_map(3 + int(source) + int(comment));
    packStr(pk, "names");
    pk.pack_array(std::uint32_t(block.size()));
    for (const auto& c : block)
        packStr(pk, c.name);
    packStr(pk, "a");
    packShapes(pk, block, &Case::a);
    packStr(pk, "b");
    packShapes(pk, block, &Case::b);
    for (auto [present, key, field] : {std::tuple{source, "source", &Case::source},
                                       std::tuple{comment, "comment", &Case::comment}})
        if (present)
        {
            packStr(pk, key);
            pk.pack_array(std::uint32_t(block.size()));
            for (const auto& c : block)
                packStr(pk, c.*field);
        }
    return std::move(out.bytes);
}
} // namespace

BinaryCaseWriter::BinaryCaseWriter(Sink sink, const std::vector<std::string>& comments)
    : sink_(std::move(sink))
{
    StringStream out;
    Packer pk(out);
    pk.pack_map(2);
    packStr(pk, "format");
    packStr(pk, kBinaryCaseFormat);
    packStr(pk, "comments");
    pk.pack_array(std::uint32_t(comments.size()));
    for (const auto& c : comments)
        packStr(pk, c);
    sink_(out.bytes);
}

void BinaryCaseWriter::add(const Case& c)
{
    const std::size_t points = std::max(c.a.points.size(), c.b.points.size());
    if (!block_.empty() && blockPoints_ + points > kWriterBlockPoints)
        flush();
    block_.push_back(c);
    blockPoints_ += points;
    if (block_.size() >= kWriterBlockCases)
        flush();
}

void BinaryCaseWriter::flush()
{
    if (block_.empty())
        return;
    sink_(blockBytes(block_));
    written_ += block_.size();
    block_.clear();
    blockPoints_ = 0;
}

void BinaryCaseWriter::finish()
{
    flush();
}

std::string binaryCaseFileBytes(const std::vector<std::string>& comments,
                                const std::vector<Case>& cases)
{
    std::string out;
    BinaryCaseWriter w([&](std::string_view b) { out.append(b); }, comments);
    for (const auto& c : cases)
        w.add(c);
    w.finish();
    return out;
}

CaseFileFormat caseFileFormatNamed(const std::string& name, const std::string& option)
{
    for (std::size_t i = 0; i < std::size(kCaseFileFormatNames); ++i)
        if (name == kCaseFileFormatNames[i])
            return CaseFileFormat(i);
    throw InputError(fmt::format("{}: unknown format '{}' (json, msgpack)", option, excerpt(name)));
}

// ---- Reading ------------------------------------------------------------------------------

bool isBinaryCaseFileStart(unsigned char b)
{
    return (b >= 0x80 && b <= 0x8F) || b == 0xDE || b == 0xDF;
}

bool isBinaryCaseFile(const std::string& path)
{
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        return false;
    std::ifstream in(path, std::ios::binary);
    const int first = in.get();
    return in && isBinaryCaseFileStart(static_cast<unsigned char>(first));
}

namespace
{
// A per-case field error (the case is rejected), as case_fields.cpp's.
struct FieldError
{
    std::string message;
};

[[noreturn]] void fieldError(std::string message)
{
    throw FieldError{std::move(message)};
}

std::string_view strOf(const msgpack::object& o)
{
    return {o.via.str.ptr, o.via.str.size};
}

// A column of little-endian values inside a bin.
struct Column
{
    const char* data = nullptr;
    std::size_t bytes = 0;
    double at(std::size_t i) const
    {
        std::uint64_t b;
        std::memcpy(&b, data + 8 * i, 8);
        return std::bit_cast<double>(toLittle(b));
    }
    std::uint32_t count(std::size_t i) const
    {
        std::uint32_t b;
        std::memcpy(&b, data + 4 * i, 4);
        return toLittle32(b);
    }
};

struct ShapeColumns
{
    Column counts, points, radius, p, q;
    std::vector<std::size_t> first; // per case: the index of its first point
    bool hasRadius = false, hasP = false, hasQ = false;
};

// The first value of `key` in a map, or nullptr.
const msgpack::object* field(const msgpack::object& map, std::string_view key)
{
    for (std::uint32_t i = 0; i < map.via.map.size; ++i)
    {
        const auto& kv = map.via.map.ptr[i];
        if (kv.key.type == msgpack::type::STR && strOf(kv.key) == key)
            return &kv.val;
    }
    return nullptr;
}

const char* typeName(const msgpack::object& o)
{
    switch (o.type)
    {
    case msgpack::type::NIL:
        return "nil";
    case msgpack::type::BOOLEAN:
        return "a boolean";
    case msgpack::type::POSITIVE_INTEGER:
    case msgpack::type::NEGATIVE_INTEGER:
        return "an integer";
    case msgpack::type::FLOAT32:
    case msgpack::type::FLOAT64:
        return "a float";
    case msgpack::type::STR:
        return "a string";
    case msgpack::type::BIN:
        return "a bin";
    case msgpack::type::ARRAY:
        return "an array";
    case msgpack::type::MAP:
        return "a map";
    default:
        return "an ext";
    }
}

// One block's columns checked against each other; per-case values are checked when the case is
// made (makeEntry). Structural errors throw InputError for the whole file.
class Block
{
  public:
    Block(const msgpack::object& o, const std::string& shown, std::size_t index, std::size_t first)
        : shown_(shown), index_(index), first_(first)
    {
        if (o.type != msgpack::type::MAP)
            fail(fmt::format("is {}, expected a map", typeName(o)));
        const msgpack::object* n = field(o, "names");
        if (n == nullptr)
            fail("missing field 'names'");
        if (n->type != msgpack::type::ARRAY || n->via.array.size == 0)
            fail("names is not a non-empty array");
        names_ = n;
        size_ = n->via.array.size;
        a_ = shape(o, "a");
        b_ = shape(o, "b");
        source_ = texts(o, "source");
        comment_ = texts(o, "comment");
    }

    std::size_t size() const { return size_; }

    CaseEntry entry(std::size_t i, const std::string& base, NameSet& names) const
    {
        CaseEntry e;
        const std::size_t index = first_ + i;
        e.label = fmt::format("{}#{}", base, index);
        try
        {
            const msgpack::object& n = names_->via.array.ptr[i];
            if (n.type != msgpack::type::STR || n.via.str.size == 0)
                fieldError("name is not a non-empty string");
            const std::string name(strOf(n));
            e.label = fmt::format("{}#{} (case '{}')", base, index, excerpt(name));
            if (name.size() > kMaxCaseNameBytes)
                fieldError(fmt::format("name is {} bytes long, more than {}", name.size(),
                                       kMaxCaseNameBytes));
            if (isControl(name)) // case_fields.hpp: as the JSON reader refuses them
                fieldError("name contains a control character or is not valid UTF-8");
            if (!names.insert(name))
                fieldError(fmt::format("duplicate case name '{}'", excerpt(name)));
            e.c.name = name;
            e.c.a = shapeAt(a_, i, "a");
            e.c.b = shapeAt(b_, i, "b");
            e.c.source = textAt(source_, i, "source");
            e.c.comment = textAt(comment_, i, "comment");
        }
        catch (const FieldError& err)
        {
            e.rejected = err.message;
            if (e.c.name.empty())
                e.c.name = e.label;
        }
        return e;
    }

  private:
    [[noreturn]] void fail(const std::string& what) const
    {
        throw InputError(
            fmt::format("{}: block {} (cases {}..): {}", shown_, index_, first_, what));
    }

    Column bin(const msgpack::object& map, const std::string& name, const char* key,
               std::size_t width, std::size_t expected, bool& present) const
    {
        const msgpack::object* o = field(map, key);
        present = o != nullptr;
        if (!present)
            return {};
        if (o->type != msgpack::type::BIN)
            fail(fmt::format("{}.{} is {}, expected a bin", name, key, typeName(*o)));
        if (o->via.bin.size != width * expected)
            fail(fmt::format("{}.{} is {} bytes, expected {} ({} values of {} bytes)", name, key,
                             o->via.bin.size, width * expected, expected, width));
        return {o->via.bin.ptr, o->via.bin.size};
    }

    ShapeColumns shape(const msgpack::object& o, const char* key) const
    {
        const msgpack::object* s = field(o, key);
        if (s == nullptr)
            fail(fmt::format("missing field '{}'", key));
        if (s->type != msgpack::type::MAP)
            fail(fmt::format("{} is {}, expected a map", key, typeName(*s)));
        ShapeColumns c;
        bool present = false;
        c.counts = bin(*s, key, "counts", 4, size_, present);
        if (!present)
            fail(fmt::format("missing field '{}.counts'", key));
        std::size_t total = 0;
        c.first.resize(size_);
        for (std::size_t i = 0; i < size_; ++i)
            c.first[i] = total, total += c.counts.count(i);
        c.points = bin(*s, key, "points", 16, total, present);
        if (!present)
            fail(fmt::format("missing field '{}.points'", key));
        c.radius = bin(*s, key, "radius", 8, size_, c.hasRadius);
        c.p = bin(*s, key, "p", 16, size_, c.hasP);
        c.q = bin(*s, key, "q", 16, size_, c.hasQ);
        return c;
    }

    const msgpack::object* texts(const msgpack::object& o, const char* key) const
    {
        const msgpack::object* t = field(o, key);
        if (t != nullptr && (t->type != msgpack::type::ARRAY || t->via.array.size != size_))
            fail(fmt::format("{} is not an array of {} strings", key, size_));
        return t;
    }

    // A finite value, or the field's error; the field is named only on an error (this runs for
    // every number of the file).
    template <class Name> static double number(double v, const Name& field)
    {
        if (std::isfinite(v)) [[likely]]
            return v;
        fieldError(fmt::format("{} is {}", field(), std::isnan(v) ? "NaN" : "infinite"));
    }

    static ShapeIn shapeAt(const ShapeColumns& c, std::size_t i, const char* k)
    {
        ShapeIn s;
        const std::size_t n = c.counts.count(i);
        if (n == 0)
            fieldError(fmt::format("{}.points is empty", k));
        if (n > kMaxShapePoints)
            fieldError(fmt::format("{}.points has {} points, more than {}", k, n, kMaxShapePoints));
        s.points.resize(n);
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t d = 0; d < 2; ++d)
                s.points[j][d] = number(c.points.at(2 * (c.first[i] + j) + d),
                                        [&] { return fmt::format("{}.points[{}][{}]", k, j, d); });
        const auto named = [k](const char* f) { return [k, f] { return std::string(k) + f; }; };
        if (c.hasRadius)
        {
            s.radius = number(c.radius.at(i), named(".radius"));
            if (s.radius < 0)
                fieldError(fmt::format("{}.radius is negative ({})", k, s.radius));
        }
        if (c.hasP)
        {
            s.px = number(c.p.at(2 * i), named(".transform.p[0]"));
            s.py = number(c.p.at(2 * i + 1), named(".transform.p[1]"));
        }
        if (c.hasQ)
        {
            s.c = number(c.q.at(2 * i), named(".transform.q[0]"));
            s.s = number(c.q.at(2 * i + 1), named(".transform.q[1]"));
            // As case_fields.cpp: any finite (c, s) but (0, 0) is a transform.
            if (s.c == 0 && s.s == 0)
                fieldError(fmt::format("{}.transform.q is (0, 0): not a rotation", k));
        }
        return s;
    }

    static std::string textAt(const msgpack::object* t, std::size_t i, const char* key)
    {
        if (t == nullptr)
            return {};
        const msgpack::object& o = t->via.array.ptr[i];
        if (o.type != msgpack::type::STR)
            fieldError(fmt::format("{} is {}, expected a string", key, typeName(o)));
        if (o.via.str.size > kMaxCommentBytes)
            fieldError(fmt::format("{} is {} bytes long, more than {}", key, o.via.str.size,
                                   kMaxCommentBytes));
        if (!isValidUtf8(strOf(o)))
            fieldError(fmt::format("{} is not valid UTF-8", key));
        return std::string(strOf(o));
    }

    const std::string& shown_;
    std::size_t index_, first_;
    const msgpack::object* names_ = nullptr;
    std::size_t size_ = 0;
    ShapeColumns a_, b_;
    const msgpack::object* source_ = nullptr;
    const msgpack::object* comment_ = nullptr;
};

// The header: {"format": "gjk-cases-msgpack/1", "comments": [...]}; returns the comments.
std::vector<std::string> readHeader(const msgpack::object& o, const std::string& shown)
{
    const auto notOurs = [&](const std::string& why)
    { return InputError(fmt::format("{}: not a {} file: {}", shown, kBinaryCaseFormat, why)); };
    if (o.type != msgpack::type::MAP)
        throw notOurs(fmt::format("the header is {}, expected a map", typeName(o)));
    const msgpack::object* format = field(o, "format");
    if (format == nullptr)
        throw notOurs("no \"format\" field");
    if (format->type != msgpack::type::STR)
        throw notOurs(fmt::format("format is {}", typeName(*format)));
    if (strOf(*format) != kBinaryCaseFormat)
        throw notOurs(fmt::format("format is \"{}\"", excerpt(strOf(*format))));
    std::vector<std::string> comments;
    const msgpack::object* cm = field(o, "comments");
    if (cm == nullptr)
        return comments;
    if (cm->type != msgpack::type::ARRAY)
        throw InputError(fmt::format("{}: \"comments\" is not an array of strings", shown));
    if (cm->via.array.size > kMaxComments)
        throw InputError(fmt::format("{}: more than {} comments", shown, kMaxComments));
    for (std::uint32_t i = 0; i < cm->via.array.size; ++i)
    {
        const msgpack::object& s = cm->via.array.ptr[i];
        if (s.type != msgpack::type::STR)
            throw InputError(fmt::format("{}: \"comments\" is not an array of strings", shown));
        if (s.via.str.size > kMaxCommentBytes)
            throw InputError(fmt::format("{}: comments[{}] is {} bytes long, more than {}", shown,
                                         i, s.via.str.size, kMaxCommentBytes));
        if (!isValidUtf8(strOf(s)))
            throw InputError(fmt::format("{}: comments[{}] is not valid UTF-8", shown, i));
        comments.emplace_back(strOf(s));
    }
    return comments;
}

// Reads a whole binary case file from `read` (which fills a buffer and returns how many bytes
// it put there, 0 at the end), block by block: memory is one block, whatever the file's size.
CaseFileSummary readBinary(const std::function<std::size_t(char*, std::size_t)>& read,
                           const std::string& sourceName,
                           const std::function<void(CaseEntry&&)>& consume)
{
    const std::string shown = shownPath(sourceName);
    std::string base = sourceName;
    if (const auto slash = base.find_last_of('/'); slash != std::string::npos)
        base = base.substr(slash + 1);
    base = excerpt(base);
    // Limits: the block bound is enforced below (nonparsed_size), these keep one object's claims
    // within it (a length field of 4 GB is refused before anything is allocated).
    msgpack::unpacker unp(
        nullptr, nullptr, MSGPACK_UNPACKER_INIT_BUFFER_SIZE,
        msgpack::unpack_limit(kMaxBlockCases, 64, kMaxBlockBytes, kMaxBlockBytes, 0, 4));
    constexpr std::size_t kRead = std::size_t(1) << 20;
    CaseFileSummary summary;
    bool header = false, end = false;
    std::size_t blocks = 0;
    NameSet names; // as the JSON reader keeps them (case_fields.hpp)
    const auto where = [&]
    {
        return header ? fmt::format("in block {} (after case {})", blocks, summary.entries)
                      : std::string("in the header");
    };
    // The unpacker consumes a value's bytes as they come, so the bytes of a value not yet complete
    // are those read past the end of the last complete one.
    std::size_t fed = 0, complete = 0;
    while (!end)
    {
        if (fed - complete > kMaxBlockBytes)
            throw InputError(fmt::format("{}: {}: a block larger than {} bytes", shown, where(),
                                         kMaxBlockBytes));
        unp.reserve_buffer(kRead);
        const std::size_t got = read(unp.buffer(), kRead);
        unp.buffer_consumed(got);
        fed += got;
        end = got == 0;
        msgpack::object_handle oh;
        while (true)
        {
            try
            {
                if (!unp.next(oh))
                    break;
            }
            catch (const msgpack::unpack_error& e)
            {
                throw InputError(
                    fmt::format("{}: {}: invalid MessagePack: {}", shown, where(), e.what()));
            }
            complete = fed - unp.nonparsed_size(); // next() resets parsed_size()
            if (!header)
            {
                summary.comments = readHeader(oh.get(), shown);
                header = true;
                continue;
            }
            const Block block(oh.get(), shown, blocks, summary.entries);
            for (std::size_t i = 0; i < block.size(); ++i)
                consume(block.entry(i, base, names));
            summary.entries += block.size();
            ++blocks;
        }
    }
    if (fed != complete)
        throw InputError(
            fmt::format("{}: {}: the file ends inside it (truncated)", shown, where()));
    if (!header)
        throw InputError(fmt::format("{}: not a {} file: empty", shown, kBinaryCaseFormat));
    return summary;
}

CaseFile collectBinary(const std::function<std::size_t(char*, std::size_t)>& read,
                       const std::string& sourceName)
{
    CaseFile file;
    file.path = sourceName;
    file.comments =
        readBinary(read, sourceName, [&](CaseEntry&& e) { file.entries.push_back(std::move(e)); })
            .comments;
    return file;
}

std::function<std::size_t(char*, std::size_t)> fileReader(std::ifstream& in,
                                                          const std::string& path)
{
    return [&in, path](char* p, std::size_t n)
    {
        in.read(p, std::streamsize(n));
        if (in.bad())
            throw InputError(fmt::format("{}: read error", shownPath(path)));
        return std::size_t(in.gcount());
    };
}

std::ifstream openBinary(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(fmt::format("{}: cannot open the file", shownPath(path)));
    return in;
}
} // namespace

CaseFileSummary streamBinaryCaseFile(const std::string& path, const std::string& sourceName,
                                     const std::function<void(CaseEntry&&)>& consume)
{
    std::ifstream in = openBinary(path);
    return readBinary(fileReader(in, sourceName), sourceName, consume);
}

CaseFile readBinaryCaseFile(const std::string& path)
{
    std::ifstream in = openBinary(path);
    return collectBinary(fileReader(in, path), path);
}

CaseFile parseBinaryCaseFile(std::string_view bytes, const std::string& sourceName)
{
    std::size_t at = 0;
    return collectBinary(
        [&](char* p, std::size_t n)
        {
            n = std::min(n, bytes.size() - at);
            std::memcpy(p, bytes.data() + at, n);
            at += n;
            return n;
        },
        sourceName);
}

} // namespace gjkval
