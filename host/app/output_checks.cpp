// output_checks.cpp — folder exists, is a folder, can be written; the format is known.
#include "app/output_checks.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <unistd.h>

#include "common/errors.h"
#include "image/image_file.h"
#include "image/image_io.h"

namespace vkpt {

namespace {

void checkWritable(const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path parent = fs::path(path).parent_path();
    const fs::path folder = parent.empty() ? fs::path(".") : parent;
    std::error_code error;
    if (fs::is_directory(path, error)) throw InputError(path + ": is a folder, not a file name");
    if (!fs::exists(folder, error))
        throw InputError(path + ": cannot write: the folder '" + folder.string() +
                         "' does not exist");
    if (!fs::is_directory(folder, error))
        throw InputError(path + ": cannot write: '" + folder.string() + "' is not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw InputError(path + ": cannot write into '" + folder.string() +
                         "': " + std::strerror(errno));
}

} // namespace

bool outputHoldsState(const std::string& outputPath) {
    return detail::lowerCaseExtension(outputPath) == ".exr";
}

std::string statePathFor(const std::string& outputPath) {
    if (outputHoldsState(outputPath)) return outputPath;
    const std::filesystem::path output(outputPath);
    return (output.parent_path() / (output.stem().string() + "_state.exr")).string();
}

void checkOutputPaths(const RenderSettings& settings) {
    const std::string& output = settings.outputPath;
    const std::string extension = detail::lowerCaseExtension(output);
    if (extension != ".png" && extension != ".pfm" && extension != ".hdr" && extension != ".exr")
        throw InputError(output + ": unknown image extension '" + extension +
                         "' (use .png, .pfm, .hdr or .exr)");
    checkWritable(output);
    checkWritable(heatMapPathFor(output));
    checkWritable(statePathFor(output));
    if (!settings.statsJsonPath.empty()) checkWritable(settings.statsJsonPath);
}

} // namespace vkpt
