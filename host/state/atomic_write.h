// atomic_write.h — files that are either whole or absent: written under a temporary name in
// the same folder, flushed to the disk, then renamed over the target (rename(2) is atomic
// within a file system), so that a kill at any moment leaves the previous checkpoint intact.
#pragma once

#include <functional>
#include <string>

namespace vkpt {

// Calls write(temporaryPath), then renames that file to `path`. When write throws or the rename
// fails, the temporary file is removed and InputError "<path>: cannot write: <reason>" thrown.
void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

// Where a state goes when its own path cannot be written at the end of a render (disk full, the
// folder gone): $TMPDIR (else /tmp)/vkpt-rescue-<pid>-<file name of path>.
std::string rescuePathFor(const std::string& path);

} // namespace vkpt
