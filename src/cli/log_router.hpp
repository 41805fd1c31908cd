// LogRouter: the stream `run` and `resume` write their log to. It keeps stdout for results and
// sends diagnostics to stderr: a line that starts with "shapevo: " (a warning, a skipped or
// damaged checkpoint, a notice) goes to stderr, every other line (the start-up line, "gen ...",
// "resuming ...", "done: ...") to stdout. Lines are passed on whole, in order per stream;
// a flush passes on what there is of the current line.
#pragma once
#include <algorithm>
#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>

namespace shapevo {

class LogRouter final : public std::streambuf {
public:
    LogRouter(std::ostream& out, std::ostream& err) : out_(out), err_(err) {}
    ~LogRouter() override { sync(); }

protected:
    int_type overflow(int_type c) override {
        if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
        put(traits_type::to_char_type(c));
        return c;
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        for (std::streamsize i = 0; i < n; ++i) put(s[i]);
        return n;
    }
    int sync() override {
        if (!line_.empty() && decide()) {
            dest_->write(line_.data(), std::streamsize(line_.size()));
            line_.clear();
        }
        out_.flush();
        err_.flush();
        return 0;
    }

private:
    static constexpr std::string_view kDiagnostic = "shapevo: ";

    /// Chooses the stream of the current line once its start is known; false while it is not.
    bool decide() {
        if (dest_) return true;
        const std::size_t n = std::min(line_.size(), kDiagnostic.size());
        if (std::string_view(line_).substr(0, n) != kDiagnostic.substr(0, n)) dest_ = &out_;
        else if (n == kDiagnostic.size()) dest_ = &err_;
        else if (!line_.empty() && line_.back() == '\n') dest_ = &out_;
        return dest_ != nullptr;
    }
    void put(char c) {
        line_.push_back(c);
        if (c != '\n') return;
        decide();
        dest_->write(line_.data(), std::streamsize(line_.size()));
        line_.clear();
        dest_ = nullptr;
    }

    std::ostream& out_;
    std::ostream& err_;
    std::string line_;
    std::ostream* dest_ = nullptr;  ///< where the current line goes; null until known
};

}  // namespace shapevo
