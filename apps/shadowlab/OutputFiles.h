#pragma once
// The files the subcommands write: output names checked before any work is
// done, the frame-number field of a sequence's name, and images renamed into
// place together once every frame succeeded.
#include <shadowlab/Image.h>

#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab::tool {

/// An output name with a printf-style integer field (`frame_%03d.png`): one
/// `%[flags][width]d` (or `i`), `%%` for a literal percent sign, nothing else.
struct FramePattern {
    std::string before, field, after; ///< the name split around its integer field ("" when it has none)
    bool hasField() const { return !field.empty(); }
    /// The name of frame `frame`: the field written with its number.
    std::string name(int frame) const;
};

/// `output` (-o) split around its frame-number field; throws Error naming -o
/// for a field other than one integer conversion.
FramePattern parseFramePattern(const std::string& output);

/// The status of `path`; throws Error "LABEL: REASON" when it cannot be
/// known (a name too long, a loop of links). A missing name is not an error
/// (file_type::not_found).
std::filesystem::file_status pathStatus(const std::filesystem::path& path, const std::string& label);

/// Checks an output PNG path (given by `flag`) before any work is done, so
/// bad paths fail fast: a .png name in an existing directory.
std::filesystem::path checkOutput(const std::string& output, const std::string& flag, const std::string& extension = ".png");

/// Checks an output directory (-o): not an existing file, its parent there.
std::filesystem::path checkOutputDirectory(const std::string& output);

/// `message` with every mention of `temporary` (a staging name) replaced by
/// `target`: errors name the file the user asked for.
std::string naming(std::string message, const std::string& temporary, const std::string& target);

/// Directories a run creates for its outputs, removed again (deepest first,
/// each only if empty) unless keep() is called: a run that fails leaves no
/// directory it made. Declare it before the PendingFiles written into them.
class MadeDirectories {
public:
    MadeDirectories() = default;
    MadeDirectories(const MadeDirectories&) = delete;
    MadeDirectories& operator=(const MadeDirectories&) = delete;
    ~MadeDirectories();
    /// Creates `dir` and any missing parent; throws Error "LABEL: cannot create the directory (REASON)".
    void make(const std::filesystem::path& dir, const std::string& label);
    void keep() { made_.clear(); }

private:
    std::vector<std::filesystem::path> made_;  ///< in the order made (parents first)
};

/// Files written under temporary names beside their targets and renamed
/// into place together by commit(): a failure at frame 7 of 10, or a target
/// that cannot be replaced (a directory of that name), leaves no file of the
/// set behind and every earlier file of those names as it was. Destroyed
/// without commit(), the temporaries are removed. Errors name the target,
/// never the temporary.
class PendingFiles {
public:
    PendingFiles() = default;
    PendingFiles(const PendingFiles&) = delete;
    PendingFiles& operator=(const PendingFiles&) = delete;
    ~PendingFiles();
    /// Writes `target`'s content with `writeTo(temporary)`.
    void write(const std::filesystem::path& target, const std::function<void(const std::filesystem::path&)>& writeTo);
    void write(const std::filesystem::path& target, const ImageRGBA8& image);
    void write(const std::filesystem::path& target, const ImageGray8& image);
    void write(const std::filesystem::path& target, const ImageGray16& image);
    /// Renames every file into place, in the order written, all or none;
    /// returns their names.
    std::vector<std::filesystem::path> commit();

private:
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> files_; ///< temporary, target
    std::set<std::filesystem::path> cleaned_;  ///< directories whose stale temporaries were removed
};

} // namespace shadowlab::tool
