#pragma once
// Writing a file whole or not at all: the bytes go to a temporary file
// beside it, checked to the last byte and through the close (a full disk
// shows there), and only then is it renamed into place.
#include <shadowlab/Export.h>

#include <filesystem>
#include <string>
#include <string_view>

namespace shadowlab {

/// Writes `bytes` to `path` whole, through `PATH.partial`, or throws
/// shadowlab::Error naming `path` and the reason ("PATH: cannot write (No
/// space left on device)") and leaves neither `path` changed nor a
/// temporary behind.
SHADOWLAB_API void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

/// Removes what killed processes left beside `target`: the files and
/// directories named `TARGET.TAG-PID` (and `TARGET.TAG-PID.partial`) whose
/// process is gone. Those of a process still running stay. It lists the
/// directory: call it once per target, not per write.
SHADOWLAB_API void removeStaleTemporaries(const std::filesystem::path& target, std::string_view tag);
/// The same for every name in `dir`: `NAME.TAG-PID` of dead processes, one
/// listing for all the files a run writes there.
SHADOWLAB_API void removeStaleTemporariesIn(const std::filesystem::path& dir, std::string_view tag);

/// A directory of results written whole or not at all: the files go into
/// `TARGET.partial-PID` beside `target`, and commit() moves its content
/// into `target` (created if missing, same-named entries replaced).
/// Destroyed without commit(), it is removed with its content. What killed
/// runs left (`TARGET.partial-PID` of dead processes) is removed first.
class SHADOWLAB_API StagingDirectory {
public:
    /// Throws Error "LABEL TARGET: cannot create the directory (...)";
    /// `label` names where the target came from ("-o", "out").
    StagingDirectory(std::filesystem::path target, const std::string& label);
    ~StagingDirectory();
    StagingDirectory(const StagingDirectory&) = delete;
    StagingDirectory& operator=(const StagingDirectory&) = delete;
    const std::filesystem::path& path() const { return staging_; }
    /// Moves the content into place; throws Error naming the entry that cannot move.
    void commit();

private:
    std::filesystem::path target_, staging_;
    bool committed_ = false;
};

} // namespace shadowlab
