#include <shadowlab/FileWrite.h>

#include <shadowlab/Error.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include <signal.h>
#include <unistd.h>

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

// Whether `digits` names a process that is gone (not this one).
bool deadProcess(const std::string& digits) {
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return false;
    const pid_t pid = static_cast<pid_t>(std::stol(digits));
    return pid != getpid() && kill(pid, 0) != 0 && errno == ESRCH;
}

} // namespace

namespace {

// Removes the entries of `dir` named `PREFIX.TAG-PID` (PREFIX: `name`, or
// any when empty), optionally followed by `.partial`, whose process is gone.
void removeStale(const fs::path& dir, const std::string& name, std::string_view tag) {
    const std::string marker = "." + std::string(tag) + "-";
    std::error_code ec;
    for (fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string entry = it->path().filename().string();
        const std::size_t at = name.empty() ? entry.rfind(marker) : (entry.rfind(name + marker, 0) == 0 ? name.size() : std::string::npos);
        if (at == std::string::npos || at == 0) continue;
        std::string digits = entry.substr(at + marker.size());
        if (const std::size_t inner = digits.find(".partial"); inner != std::string::npos) digits.resize(inner);  // its own write's temporary
        if (!deadProcess(digits)) continue;
        std::error_code removeError;
        fs::remove_all(it->path(), removeError);
    }
}

} // namespace

void removeStaleTemporaries(const fs::path& target, std::string_view tag) { removeStale(target.parent_path(), target.filename().string(), tag); }

void removeStaleTemporariesIn(const fs::path& dir, std::string_view tag) { removeStale(dir, std::string(), tag); }

void writeFileAtomically(const fs::path& path, std::string_view bytes) {
    const auto fail = [&](const std::string& reason) { return Error(path.string() + ": cannot write (" + reason + ")"); };
    std::error_code ec;
    const fs::path dir = path.parent_path();
    if (!dir.empty() && !fs::is_directory(dir, ec))
        throw fail("directory " + dir.string() + (ec ? ": " + ec.message() : " does not exist"));
    if (fs::is_directory(path, ec)) throw fail("a directory of that name is in the way");
    // One name per target, as before: a killed write's temporary is replaced
    // by the next write to that name (the tool's names are per process
    // already: NAME.pending-PID, OUT.partial-PID/), and no directory is
    // listed for every file written.
    fs::path tmp = path;
    tmp += ".partial";
    std::FILE* file = std::fopen(tmp.string().c_str(), "wb");
    if (!file) throw fail(std::strerror(errno));
    int error = 0;
    if (!bytes.empty() && std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size()) error = errno ? errno : EIO;
    if (std::fflush(file) != 0 && !error) error = errno ? errno : EIO;
    if (std::fclose(file) != 0 && !error) error = errno ? errno : EIO;
    if (error) {
        fs::remove(tmp, ec);
        throw fail(std::strerror(error));
    }
    fs::rename(tmp, path, ec);
    if (ec) {
        std::error_code ignored;  // removing the temporary must not overwrite the rename's error
        fs::remove(tmp, ignored);
        throw fail(ec.message());
    }
}

StagingDirectory::StagingDirectory(fs::path target, const std::string& label) : target_(std::move(target)) {
    removeStaleTemporaries(target_, "partial");  // OUT.partial-PID of runs that were killed
    staging_ = target_;
    staging_ += ".partial-" + std::to_string(getpid());
    std::error_code ec;
    fs::remove_all(staging_, ec);
    fs::create_directories(staging_, ec);
    if (ec) throw Error(label + " " + target_.string() + ": cannot create the directory (" + ec.message() + ")");
}

StagingDirectory::~StagingDirectory() {
    if (committed_) return;
    std::error_code ec;
    fs::remove_all(staging_, ec);
}

void StagingDirectory::commit() {
    std::error_code ec;
    if (!fs::exists(target_, ec)) {
        fs::rename(staging_, target_, ec);
        if (ec) throw Error(target_.string() + ": cannot move the results into place (" + ec.message() + ")");
    } else {
        for (const fs::directory_entry& entry : fs::directory_iterator(staging_, ec)) {
            const fs::path destination = target_ / entry.path().filename();
            fs::remove_all(destination, ec);
            fs::rename(entry.path(), destination, ec);
            if (ec) throw Error(destination.string() + ": cannot move into place (" + ec.message() + ")");
        }
        fs::remove_all(staging_, ec);
    }
    committed_ = true;
}

} // namespace shadowlab
