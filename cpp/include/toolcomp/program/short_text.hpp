#pragma once
// ShortText: the text of a token (its key "X", "CR", "FMAX", its word as written "X100", a
// label), in 8 bytes where std::string takes 32: up to 6 characters in place, longer ones
// ("GETTCOR", a quoted name) on the heap. A million-block program holds millions of tokens,
// and each byte of a token is memory the kernel zeroes and the interpreter reads again.
//
// It reads as a std::string_view (comparisons, find, starts_with ...) and converts to a
// std::string where one is needed; substr returns a std::string, as std::string's does.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

namespace toolcomp {

class ShortText {
public:
    static constexpr std::size_t npos = std::string_view::npos;

    ShortText() noexcept { set_inline_size(0); }
    ShortText(std::string_view s) { init(s); }  // NOLINT: implicit, as std::string from a literal
    ShortText(const char* s) { init(s); }       // NOLINT
    ShortText(const std::string& s) { init(s); }  // NOLINT
    ShortText(const ShortText& o) { init(o.view()); }
    ShortText(ShortText&& o) noexcept {
        std::memcpy(buf_, o.buf_, sizeof buf_);
        o.set_inline_size(0);
    }
    ShortText& operator=(const ShortText& o) {
        if (this != &o) assign(o.view());
        return *this;
    }
    ShortText& operator=(ShortText&& o) noexcept {
        if (this != &o) {
            release();
            std::memcpy(buf_, o.buf_, sizeof buf_);
            o.set_inline_size(0);
        }
        return *this;
    }
    ShortText& operator=(std::string_view s) { return assign(s); }
    ShortText& operator=(const char* s) { return assign(std::string_view(s)); }
    ShortText& operator=(const std::string& s) { return assign(std::string_view(s)); }
    ~ShortText() { release(); }

    ShortText& assign(std::string_view s) {
        if (!on_heap() && s.size() <= kInline) {  // in place (s may lie in this text)
            if (!s.empty()) std::memmove(buf_ + 1, s.data(), s.size());
            set_inline_size(s.size());
            return *this;
        }
        ShortText t(s);  // s may lie in this text
        *this = std::move(t);
        return *this;
    }
    ShortText& assign(std::size_t n, char c) {
        if (!on_heap() && n <= kInline) {
            std::memset(buf_ + 1, c, n);
            set_inline_size(n);
            return *this;
        }
        return assign(std::string(n, c));
    }
    ShortText& append(std::string_view s) {
        if (!on_heap() && size() + s.size() <= kInline) {  // in place (s may lie in this text)
            const std::size_t n = size();
            if (!s.empty()) std::memmove(buf_ + 1 + n, s.data(), s.size());
            set_inline_size(n + s.size());
            return *this;
        }
        std::string joined(view());
        joined.append(s);
        return assign(joined);
    }
    ShortText& operator+=(std::string_view s) { return append(s); }
    ShortText& operator+=(char c) { return append(std::string_view(&c, 1)); }
    void push_back(char c) { append(std::string_view(&c, 1)); }
    void clear() noexcept {
        release();
        set_inline_size(0);
    }
    void reserve(std::size_t) noexcept {}  // a ShortText is written once

    std::size_t size() const noexcept { return on_heap() ? heap_size() : static_cast<unsigned char>(buf_[0]) >> 1; }
    std::size_t length() const noexcept { return size(); }
    bool empty() const noexcept { return size() == 0; }
    const char* data() const noexcept { return on_heap() ? heap_ptr() : buf_ + 1; }
    char* data() noexcept { return on_heap() ? heap_ptr() : buf_ + 1; }
    const char* c_str() const noexcept { return data(); }
    std::string_view view() const noexcept { return {data(), size()}; }
    operator std::string_view() const noexcept { return view(); }  // NOLINT
    operator std::string() const { return std::string(view()); }  // NOLINT
    std::string str() const { return std::string(view()); }

    char operator[](std::size_t i) const noexcept { return data()[i]; }
    char& operator[](std::size_t i) noexcept { return data()[i]; }
    char front() const noexcept { return data()[0]; }
    char back() const noexcept { return data()[size() - 1]; }
    const char* begin() const noexcept { return data(); }
    const char* end() const noexcept { return data() + size(); }

    std::string substr(std::size_t pos = 0, std::size_t n = npos) const { return std::string(view().substr(pos, n)); }
    std::size_t find(std::string_view s, std::size_t pos = 0) const noexcept { return view().find(s, pos); }
    std::size_t find(char c, std::size_t pos = 0) const noexcept { return view().find(c, pos); }
    std::size_t rfind(std::string_view s, std::size_t pos = npos) const noexcept { return view().rfind(s, pos); }
    std::size_t rfind(char c, std::size_t pos = npos) const noexcept { return view().rfind(c, pos); }
    std::size_t find_first_of(std::string_view s, std::size_t pos = 0) const noexcept { return view().find_first_of(s, pos); }
    std::size_t find_first_not_of(std::string_view s, std::size_t pos = 0) const noexcept {
        return view().find_first_not_of(s, pos);
    }
    std::size_t find_last_of(std::string_view s, std::size_t pos = npos) const noexcept { return view().find_last_of(s, pos); }
    bool starts_with(std::string_view s) const noexcept { return view().starts_with(s); }
    bool starts_with(char c) const noexcept { return view().starts_with(c); }
    bool ends_with(std::string_view s) const noexcept { return view().ends_with(s); }
    int compare(std::string_view s) const noexcept { return view().compare(s); }
    int compare(std::size_t pos, std::size_t n, std::string_view s) const { return view().compare(pos, n, s); }

    friend bool operator==(const ShortText& a, const ShortText& b) noexcept { return a.view() == b.view(); }
    friend bool operator==(const ShortText& a, std::string_view b) noexcept { return a.view() == b; }
    friend bool operator==(const ShortText& a, const char* b) noexcept { return a.view() == std::string_view(b); }
    friend bool operator==(const ShortText& a, const std::string& b) noexcept { return a.view() == std::string_view(b); }
    friend auto operator<=>(const ShortText& a, const ShortText& b) noexcept { return a.view() <=> b.view(); }
    friend auto operator<=>(const ShortText& a, std::string_view b) noexcept { return a.view() <=> b; }

    friend std::string operator+(const ShortText& a, std::string_view b) { return std::string(a.view()).append(b); }
    friend std::string operator+(const ShortText& a, const char* b) { return std::string(a.view()).append(b); }
    friend std::string operator+(const ShortText& a, const std::string& b) { return std::string(a.view()).append(b); }
    friend std::string operator+(const ShortText& a, const ShortText& b) { return std::string(a.view()).append(b.view()); }
    friend std::string operator+(const ShortText& a, char b) { return std::string(a.view()) + b; }
    friend std::string operator+(std::string a, const ShortText& b) { return a.append(b.view()); }
    friend std::string operator+(const char* a, const ShortText& b) { return std::string(a).append(b.view()); }
    friend std::string operator+(char a, const ShortText& b) { return std::string(1, a).append(b.view()); }

private:
    // In place: the first byte is 2 * size + 1 (odd), the characters follow with a NUL after
    // them. On the heap: the bytes hold a pointer to a block of 32-bit words (so its lowest
    // byte, the first on a little-endian machine, is even): the size, then the characters
    // and a NUL.
    static constexpr std::size_t kInline = 6;

    bool on_heap() const noexcept { return (static_cast<unsigned char>(buf_[0]) & 1) == 0; }
    std::uint32_t* block() const noexcept {
        std::uint32_t* p;
        std::memcpy(&p, buf_, sizeof p);
        return p;
    }
    char* heap_ptr() const noexcept { return reinterpret_cast<char*>(block() + 1); }
    std::size_t heap_size() const noexcept { return block()[0]; }
    void set_inline_size(std::size_t n) noexcept {
        buf_[1 + n] = '\0';
        buf_[0] = static_cast<char>(2 * n + 1);
    }
    void init(std::string_view s) {
        if (s.size() <= kInline) {
            if (!s.empty()) std::memcpy(buf_ + 1, s.data(), s.size());
            set_inline_size(s.size());
            return;
        }
        if (s.size() > UINT32_MAX - 8) throw std::length_error("ShortText longer than 4 GB");
        std::uint32_t* p = new std::uint32_t[1 + (s.size() + 4) / 4];  // the size, the characters and a NUL
        p[0] = static_cast<std::uint32_t>(s.size());
        char* d = reinterpret_cast<char*>(p + 1);
        std::memcpy(d, s.data(), s.size());
        d[s.size()] = '\0';
        std::memcpy(buf_, &p, sizeof p);
    }
    void release() noexcept {
        if (on_heap()) delete[] block();
    }

    char buf_[8];
};

static_assert(std::endian::native == std::endian::little, "the in-place mark is the pointer's lowest byte");
static_assert(sizeof(void*) <= 8 && alignof(std::uint32_t) >= 2);
static_assert(sizeof(ShortText) == 8);

}  // namespace toolcomp
