#pragma once
// The files the subcommands write: output names checked before any work is
// done, the frame-number field of a sequence's name, and images renamed into
// place together once every frame succeeded.
#include <shadowlab/Image.h>

#include <filesystem>
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

/// Checks an output PNG path (given by `flag`) before any work is done, so
/// bad paths fail fast: a .png name in an existing directory.
std::filesystem::path checkOutput(const std::string& output, const std::string& flag);

/// Checks an output directory (-o): not an existing file, its parent there.
std::filesystem::path checkOutputDirectory(const std::string& output);

/// Images written under temporary names beside their targets and renamed
/// into place together by commit(): a failure at frame 7 of 10 leaves no
/// frame behind. Destroyed without commit(), the temporaries are removed.
class PendingImages {
public:
    PendingImages() = default;
    PendingImages(const PendingImages&) = delete;
    PendingImages& operator=(const PendingImages&) = delete;
    ~PendingImages();
    void write(const std::filesystem::path& target, const ImageRGBA8& image);
    /// Renames every image into place, in the order written; returns their names.
    std::vector<std::filesystem::path> commit();

private:
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> files_; ///< temporary, target
};

} // namespace shadowlab::tool
