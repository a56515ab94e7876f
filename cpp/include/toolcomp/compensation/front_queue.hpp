#pragma once
// FrontQueue: a vector that gives up its first elements cheaply. A compensation stage's
// look-ahead window takes a move at the back and lets the oldest go at the front every
// block; erasing the front of a vector moves every move behind it (a Motion is 300 bytes),
// so the front is only marked gone and the storage compacted when half of it is.
#include <cstddef>
#include <utility>
#include <vector>

namespace toolcomp {

template <typename T>
class FrontQueue {
public:
    std::size_t size() const { return items_.size() - head_; }
    bool empty() const { return size() == 0; }
    T& operator[](std::size_t i) { return items_[head_ + i]; }
    const T& operator[](std::size_t i) const { return items_[head_ + i]; }
    T* begin() { return items_.data() + head_; }
    T* end() { return items_.data() + items_.size(); }
    const T* begin() const { return items_.data() + head_; }
    const T* end() const { return items_.data() + items_.size(); }
    T& back() { return items_.back(); }

    template <typename... Args>
    T& emplace_back(Args&&... args) {
        return items_.emplace_back(std::forward<Args>(args)...);
    }
    // The first n go.
    void pop_front(std::size_t n) {
        head_ += n;
        if (head_ == items_.size()) {
            clear();
        } else if (head_ >= kCompactAt && 2 * head_ >= items_.size()) {
            items_.erase(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(head_));
            head_ = 0;
        }
    }
    // All but the first n go.
    void truncate(std::size_t n) { items_.erase(items_.begin() + static_cast<std::ptrdiff_t>(head_ + n), items_.end()); }
    void clear() {
        items_.clear();
        head_ = 0;
    }

private:
    static constexpr std::size_t kCompactAt = 16;
    std::vector<T> items_;
    std::size_t head_ = 0;  // the elements before it are gone
};

}  // namespace toolcomp
