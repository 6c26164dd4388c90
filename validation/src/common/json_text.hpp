// Helpers for JSON read as text: where in the text a parse error is.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>

namespace gjkval
{

// Line and column (both from 1) of a byte offset in text.
inline std::pair<std::size_t, std::size_t> lineColumn(const std::string& text,
                                                      std::size_t byteOffset)
{
    std::size_t line = 1, column = 1;
    const std::size_t end = std::min(byteOffset, text.size());
    for (std::size_t i = 0; i < end; ++i)
    {
        if (text[i] == '\n')
        {
            ++line;
            column = 1;
        }
        else
            ++column;
    }
    return {line, column};
}

} // namespace gjkval
