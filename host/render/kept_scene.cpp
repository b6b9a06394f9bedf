// kept_scene.cpp — block hashes against the frame before's, and uploads of what differs.
#include "render/kept_scene.h"

#include <algorithm>
#include <cstring>

#include "common/content_hash.h"
#include "gpu/context.h"
#include "gpu/upload.h"

namespace vkpt {

namespace {

std::vector<std::uint64_t> blockHashes(std::span<const std::byte> bytes) {
    std::vector<std::uint64_t> hashes;
    for (std::uint64_t offset = 0; offset < bytes.size(); offset += KeptDeviceScene::kBlockBytes)
        hashes.push_back(hashBytes(bytes.subspan(
            offset, std::min<std::uint64_t>(KeptDeviceScene::kBlockBytes, bytes.size() - offset))));
    return hashes;
}

// Writes bytes [begin, end) of the array into the chunks that hold them.
void uploadRange(GpuContext& context, const SceneArray& array, std::span<const std::byte> bytes,
                 std::uint64_t begin, std::uint64_t end) {
    std::uint64_t chunkStart = 0;
    for (const Buffer& chunk : array.chunks) {
        const std::uint64_t chunkEnd = chunkStart + chunk.size();
        const std::uint64_t from = std::max(begin, chunkStart);
        const std::uint64_t to = std::min(end, chunkEnd);
        if (from < to)
            uploadBytes(context, chunk, bytes.subspan(from, to - from), from - chunkStart);
        chunkStart = chunkEnd;
    }
}

std::uint64_t arrayBytes(const SceneArray& array) {
    std::uint64_t total = 0;
    for (const Buffer& chunk : array.chunks)
        total += chunk.size();
    return total;
}

} // namespace

DeviceScene KeptDeviceScene::upload(GpuContext& context, PreparedScene& scene) {
    stats_ = {};
    const std::span<const SceneArrayDesc> list = sceneArrayList();
    std::optional<DeviceScene> last = std::move(last_);
    last_.reset();
    // Arrays whose size changed are freed before anything is uploaded: the device then holds the
    // scene once, as a first frame does, and the memory check sees what is really in use.
    std::vector<char> keeps(list.size(), 0);
    std::uint64_t onDevice = 0;
    if (last && last->arrays.size() == list.size() && blockHashes_.size() == list.size()) {
        for (std::size_t i = 0; i < list.size(); ++i) {
            SceneArray& old = last->arrays[i];
            const std::uint64_t bytes = list[i].bytes(scene).size();
            keeps[i] = !old.chunks.empty() && arrayBytes(old) == bytes;
            if (keeps[i]) {
                onDevice += bytes;
            } else {
                old = SceneArray{};
            }
        }
    }
    DeviceScene d = beginSceneUpload(context, scene, onDevice);
    blockHashes_.resize(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
        const SceneArrayDesc& desc = list[i];
        const std::span<const std::byte> bytes = desc.bytes(scene);
        std::vector<std::uint64_t> hashes = blockHashes(bytes);
        if (keeps[i]) {
            SceneArray array = std::move(last->arrays[i]);
            for (std::size_t b = 0; b < hashes.size(); ++b) {
                const std::uint64_t begin = b * kBlockBytes;
                const std::uint64_t end =
                    std::min<std::uint64_t>(begin + kBlockBytes, bytes.size());
                if (b < blockHashes_[i].size() && blockHashes_[i][b] == hashes[b]) {
                    stats_.keptBytes += end - begin;
                    continue;
                }
                uploadRange(context, array, bytes, begin, end);
                stats_.uploadedBytes += end - begin;
            }
            d.arrays.push_back(std::move(array));
        } else {
            d.arrays.push_back(uploadSceneArray(context, desc, bytes));
            stats_.uploadedBytes += bytes.size();
        }
        blockHashes_[i] = std::move(hashes);
        desc.release(scene);
    }
    return d;
}

} // namespace vkpt
