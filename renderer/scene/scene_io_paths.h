// Paths inside scene_io's documents are relative to the file that names them; these turn them to
// and from that file's folder. Internal to the scene layer.
#pragma once

#include <filesystem>
#include <string>

namespace wavelit::scene {

// The folder `file` sits in ("." for a bare name), which its relative paths start from.
inline std::filesystem::path folderOf(const std::string& file) {
    std::filesystem::path dir = std::filesystem::path(file).parent_path();
    return dir.empty() ? std::filesystem::path(".") : dir;
}

// `file` as a portable relative path from `folder` (absolute paths are never stored).
inline std::string relativeTo(const std::string& file, const std::filesystem::path& folder) {
    namespace fs = std::filesystem;
    return fs::absolute(file).lexically_normal().lexically_relative(fs::absolute(folder).lexically_normal()).generic_string();
}

} // namespace wavelit::scene
