#include "io/VtuArrayLengths.hpp"

#include "core/InputError.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace sph
{

namespace
{

using Attributes = std::map<std::string, std::string>;

Attributes attributesOf(const std::string& text)
{
    static const std::regex attribute(R"re((\w+)\s*=\s*"([^"]*)")re");
    Attributes found;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), attribute);
         it != std::sregex_iterator(); ++it)
    {
        found[(*it)[1]] = (*it)[2];
    }
    return found;
}

// A whole number attribute, `otherwise` when absent or not one.
std::uint64_t wholeNumber(const Attributes& attributes, const std::string& key,
                          std::uint64_t otherwise)
{
    const auto found = attributes.find(key);
    if (found == attributes.end() || found->second.empty() ||
        found->second.find_first_not_of("0123456789") != std::string::npos ||
        found->second.size() > 18)
    {
        return otherwise;
    }
    return std::strtoull(found->second.c_str(), nullptr, 10);
}

std::size_t bytesOf(const std::string& type)
{
    static const std::map<std::string, std::size_t> sizes{
        {"Int8", 1},  {"UInt8", 1},  {"Int16", 2},   {"UInt16", 2},  {"Int32", 4},
        {"UInt32", 4}, {"Float32", 4}, {"Int64", 8}, {"UInt64", 8}, {"Float64", 8}};
    const auto found = sizes.find(type);
    return found == sizes.end() ? 0 : found->second;
}

std::vector<unsigned char> fromBase64(const std::string& text)
{
    static const std::string alphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<unsigned char> bytes;
    unsigned int bits = 0;
    int count = 0;
    for (const char c : text)
    {
        const auto value = alphabet.find(c);
        if (value == std::string::npos)
        {
            continue; // '=' and blanks
        }
        bits = (bits << 6) | static_cast<unsigned int>(value);
        count += 6;
        if (count >= 8)
        {
            count -= 8;
            bytes.push_back(static_cast<unsigned char>((bits >> count) & 0xff));
        }
    }
    return bytes;
}

// How a file stores its binary blocks: a header of 1 (raw) or 3 + blocks (compressed) unsigned
// integers of `word` bytes before each array's data.
struct Blocks
{
    std::size_t word = 4;
    bool compressed = false;

    std::uint64_t at(const unsigned char* bytes, std::size_t index) const
    {
        std::uint64_t value = 0;
        if (word == 8)
        {
            std::memcpy(&value, bytes + 8 * index, 8);
        }
        else
        {
            std::uint32_t small = 0;
            std::memcpy(&small, bytes + 4 * index, 4);
            value = small;
        }
        return value;
    }
    std::size_t headerBytes() const { return (compressed ? 3 : 1) * word; }
    // The uncompressed length of the data after the header `bytes` (headerBytes() long).
    std::uint64_t dataBytes(const unsigned char* bytes) const
    {
        if (!compressed)
        {
            return at(bytes, 0);
        }
        const std::uint64_t blocks = at(bytes, 0);
        const std::uint64_t size = at(bytes, 1);
        const std::uint64_t last = at(bytes, 2);
        return blocks == 0 ? 0 : (blocks - 1) * size + (last != 0 ? last : size);
    }
};

class LengthCheck
{
public:
    explicit LengthCheck(const std::filesystem::path& file) : file_(file), in_(file, std::ios::binary)
    {
        std::string chunk(1 << 16, '\0');
        while (in_ && header_.find("<AppendedData") == std::string::npos &&
               header_.size() < (64u << 20))
        {
            in_.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
            header_.append(chunk.data(), static_cast<std::size_t>(in_.gcount()));
        }
        in_.clear();
        const auto appended = header_.find("<AppendedData");
        if (appended != std::string::npos)
        {
            const auto underscore = header_.find('_', header_.find('>', appended));
            if (underscore != std::string::npos)
            {
                appendedStart_ = underscore + 1;
                appendedRaw_ = attributesOf(header_.substr(appended, underscore - appended))
                                   .count("encoding") == 0 ||
                               attributesOf(header_.substr(appended, underscore - appended))
                                       .at("encoding") == "raw";
            }
            header_.resize(appended);
        }
    }

    void run()
    {
        static const std::regex tag(R"re(<(/?)(\w+)([^>]*)>)re");
        std::uint64_t points = 0;
        bool pointArrays = false;
        for (auto it = std::sregex_iterator(header_.begin(), header_.end(), tag);
             it != std::sregex_iterator(); ++it)
        {
            const bool closing = (*it)[1].length() > 0;
            const std::string name = (*it)[2];
            const Attributes attributes = attributesOf((*it)[3]);
            if (!closing && name == "VTKFile")
            {
                blocks_.word = attributes.count("header_type") && attributes.at("header_type") == "UInt64" ? 8 : 4;
                blocks_.compressed = attributes.count("compressor") > 0;
            }
            else if (!closing && name == "Piece")
            {
                points = wholeNumber(attributes, "NumberOfPoints", 0);
            }
            else if (name == "PointData" || name == "Points")
            {
                pointArrays = !closing;
            }
            else if (!closing && name == "DataArray" && pointArrays)
            {
                const std::size_t end = static_cast<std::size_t>(it->position() + it->length());
                check(attributes, points, end);
            }
        }
    }

private:
    void check(const Attributes& attributes, std::uint64_t points, std::size_t tagEnd)
    {
        const std::uint64_t components = wholeNumber(attributes, "NumberOfComponents", 1);
        const std::size_t size = attributes.count("type") ? bytesOf(attributes.at("type")) : 0;
        const std::string format = attributes.count("format") ? attributes.at("format") : "";
        const std::string name = attributes.count("Name") ? attributes.at("Name") : "Points";
        const std::uint64_t expected = points * components;
        std::optional<std::uint64_t> values;
        if (format == "ascii")
        {
            const auto close = header_.find("</DataArray>", tagEnd);
            std::istringstream words(header_.substr(tagEnd, close - tagEnd));
            std::uint64_t count = 0;
            for (std::string word; words >> word;)
            {
                ++count;
            }
            values = count;
        }
        else if (size > 0 && format == "appended" && appendedStart_ && appendedRaw_ &&
                 attributes.count("offset"))
        {
            std::vector<unsigned char> bytes(blocks_.headerBytes());
            in_.seekg(static_cast<std::streamoff>(*appendedStart_ +
                                                  wholeNumber(attributes, "offset", 0)));
            if (in_.read(reinterpret_cast<char*>(bytes.data()),
                         static_cast<std::streamsize>(bytes.size())))
            {
                values = blocks_.dataBytes(bytes.data()) / size;
            }
            in_.clear();
        }
        else if (size > 0 && format == "binary")
        {
            // The header is base64 on its own when compressed, with the data when not: its
            // first 4 x ceil(bytes / 3) characters hold it either way.
            const std::size_t first = header_.find_first_not_of(" \t\r\n", tagEnd);
            const std::size_t characters = 4 * ((blocks_.headerBytes() + 2) / 3);
            const auto bytes = fromBase64(header_.substr(first, characters));
            if (first != std::string::npos && bytes.size() >= blocks_.headerBytes())
            {
                values = blocks_.dataBytes(bytes.data()) / size;
            }
        }
        if (values && *values != expected)
        {
            throw InputError("cannot read '" + file_.string() + "': its array '" + name +
                                 "' holds " + std::to_string(*values) + " values for " +
                                 std::to_string(points) + " points (" + std::to_string(expected) +
                                 " expected: " + std::to_string(components) + " per point)",
                             {"The file is damaged or was not written by sphSolid; write it "
                              "again (sphParticles, or the run that wrote it)."});
        }
    }

    std::filesystem::path file_;
    std::ifstream in_;
    std::string header_; // the XML before any appended data
    std::optional<std::size_t> appendedStart_;
    bool appendedRaw_ = false;
    Blocks blocks_;
};

} // namespace

void checkVtuArrayLengths(const std::filesystem::path& file)
{
    LengthCheck(file).run();
}

} // namespace sph
