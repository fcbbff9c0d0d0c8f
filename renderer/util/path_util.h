// Small path helpers shared by the file readers and the CLI.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace wavelit::util {

// ".EXR" -> ".exr": file types are chosen by extension, case-insensitively.
inline std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

} // namespace wavelit::util
