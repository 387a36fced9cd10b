// The files the subcommands write (OutputFiles.h).
#include "OutputFiles.h"

#include "Interrupt.h"

#include <shadowlab/Error.h>
#include <shadowlab/FileWrite.h>

#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <string_view>
#include <system_error>

namespace shadowlab::tool {

namespace fs = std::filesystem;

std::string FramePattern::name(int frame) const {
    if (!hasField()) return before;
    char number[64];
    std::snprintf(number, sizeof number, field.c_str(), frame);  // field was checked to be one integer conversion
    return before + number + after;
}

FramePattern parseFramePattern(const std::string& output) {
    FramePattern p;
    std::string* part = &p.before;
    for (std::size_t i = 0; i < output.size(); ++i) {
        if (output[i] != '%') {
            *part += output[i];
            continue;
        }
        if (i + 1 < output.size() && output[i + 1] == '%') {
            *part += '%';
            ++i;
            continue;
        }
        const std::size_t start = i++;
        while (i < output.size() && std::string_view("-+ 0#").find(output[i]) != std::string_view::npos) ++i;
        const std::size_t widthStart = i;
        while (i < output.size() && std::isdigit(static_cast<unsigned char>(output[i]))) ++i;
        // At most 20 digits: any int fits, and the formatted number always fits its buffer (a width of 999 was cut silently).
        if (i - widthStart > 2 || (i > widthStart && std::stoi(output.substr(widthStart, i - widthStart)) > 20))
            throw Error("-o " + output + ": the frame number's width is " + output.substr(widthStart, i - widthStart) + " (at most 20)");
        if (i >= output.size() || (output[i] != 'd' && output[i] != 'i'))
            throw Error("-o " + output + ": '%' starts a frame number field such as %d or %03d (write %% for a percent sign)");
        if (p.hasField()) throw Error("-o " + output + ": more than one frame number field");
        p.field = output.substr(start, i + 1 - start);
        part = &p.after;
    }
    return p;
}

fs::file_status pathStatus(const fs::path& path, const std::string& label) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    // A missing name is a status (not_found); a name too long or a loop of links is not.
    if (status.type() == fs::file_type::none) throw Error(label + ": " + ec.message());
    return status;
}

fs::path checkOutput(const std::string& output, const std::string& flag, const std::string& extension) {
    const fs::path path(output);
    const std::string label = flag + " " + output;
    if (fs::is_directory(pathStatus(path, label))) throw Error(label + ": is a directory (expected a " + extension + " file name)");
    std::string given = path.extension().string();
    for (char& c : given) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (given != extension) throw Error(label + ": expected a " + extension + " file name");
    const fs::path dir = path.parent_path();
    if (!dir.empty() && !fs::is_directory(pathStatus(dir, label)))
        throw Error(label + ": directory " + dir.string() + " does not exist");
    return path;
}

fs::path checkOutputDirectory(const std::string& output) {
    const fs::path dir(output);
    const std::string label = "-o " + output;
    const fs::file_status status = pathStatus(dir, label);
    if (fs::exists(status) && !fs::is_directory(status)) throw Error(label + ": exists and is not a directory");
    if (!dir.parent_path().empty() && !fs::is_directory(pathStatus(dir.parent_path(), label)))
        throw Error(label + ": directory " + dir.parent_path().string() + " does not exist");
    return dir;
}

namespace {

fs::path besideTarget(const fs::path& target, const char* what) {
    fs::path p = target;
    p += std::string(".") + what + "-" + std::to_string(getpid());
    return p;
}

} // namespace

std::string naming(std::string message, const std::string& temporary, const std::string& target) {
    for (std::size_t at = message.find(temporary); at != std::string::npos; at = message.find(temporary, at + target.size()))
        message.replace(at, temporary.size(), target);
    return message;
}

MadeDirectories::~MadeDirectories() {
    for (auto it = made_.rbegin(); it != made_.rend(); ++it) {
        std::error_code ec;
        fs::remove(*it, ec);  // only if empty: fs::remove does not remove a directory with files
    }
}

void MadeDirectories::make(const fs::path& dir, const std::string& label) {
    std::vector<fs::path> missing;
    std::error_code ec;
    for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
        missing.push_back(p);
        if (p == p.parent_path()) break;
    }
    fs::create_directories(dir, ec);
    if (ec) throw Error(label + ": cannot create the directory (" + ec.message() + ")");
    made_.insert(made_.end(), missing.rbegin(), missing.rend());
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) removeOnForcedEnd(*it, OnForcedEnd::IfEmpty);
}

PendingFiles::~PendingFiles() {
    std::error_code ec;
    for (const auto& [temporary, target] : files_) fs::remove(temporary, ec);
}

void PendingFiles::write(const fs::path& target, const std::function<void(const fs::path&)>& writeTo) {
    throwIfInterrupted();
    // NAME.pending-PID of runs that were killed, once per directory written to.
    if (fs::path dir = target.parent_path(); cleaned_.insert(dir).second) {
        removeStaleTemporariesIn(dir, "pending");
        removeOnForcedEnd(dir, OnForcedEnd::OurPendingFiles);  // this run's, if a second interrupt ends it at once
    }
    const fs::path temporary = besideTarget(target, "pending");
    files_.emplace_back(temporary, target);  // first: removed even if the write fails half way
    try {
        writeTo(temporary);
    } catch (const Error& e) {
        throw Error(naming(e.what(), temporary.string(), target.string()));
    }
}

void PendingFiles::write(const fs::path& target, const ImageRGBA8& image) {
    write(target, [&](const fs::path& p) { writePng(p, image); });
}
void PendingFiles::write(const fs::path& target, const ImageGray8& image) {
    write(target, [&](const fs::path& p) { writePng(p, image); });
}
void PendingFiles::write(const fs::path& target, const ImageGray16& image) {
    write(target, [&](const fs::path& p) { writePng16(p, image); });
}

std::vector<fs::path> PendingFiles::commit() {
    // Every target replaceable first: a directory of that name is not.
    for (const auto& [temporary, target] : files_)
        if (std::error_code ec; fs::is_directory(target, ec)) throw Error(target.string() + ": cannot write (a directory of that name is in the way)");
    // Then renamed one by one, each earlier file of the name kept aside
    // until all are in place, and put back if one fails.
    struct Done {
        fs::path target, previous;  ///< previous: the earlier file, moved aside ("" if none)
    };
    std::vector<Done> done;
    std::string failure;
    for (const auto& [temporary, target] : files_) {
        std::error_code ec;
        Done d{target, {}};
        if (fs::exists(fs::symlink_status(target, ec))) {
            d.previous = besideTarget(target, "previous");
            fs::rename(target, d.previous, ec);
            if (ec) {
                failure = target.string() + ": cannot write (" + ec.message() + ")";
                break;
            }
        }
        fs::rename(temporary, target, ec);
        if (ec) {
            failure = target.string() + ": cannot write (" + ec.message() + ")";
            if (!d.previous.empty()) fs::rename(d.previous, target, ec);
            break;
        }
        done.push_back(d);
    }
    std::error_code ignored;
    if (!failure.empty()) {
        for (auto it = done.rbegin(); it != done.rend(); ++it) {
            fs::remove(it->target, ignored);
            if (!it->previous.empty()) fs::rename(it->previous, it->target, ignored);
        }
        throw Error(failure);  // the destructor removes the temporaries
    }
    std::vector<fs::path> written;
    for (const Done& d : done) {
        if (!d.previous.empty()) fs::remove(d.previous, ignored);
        written.push_back(d.target);
    }
    files_.clear();
    return written;
}

} // namespace shadowlab::tool
