// glslrun::Span<T>: a pointer and a count, the view the public header takes
// and returns where C++20 code would use std::span, so that glslrun.h
// compiles as C++17 too. Under C++20 it converts to and from std::span.
#pragma once
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <utility>
#if __cplusplus >= 202002L
#include <span>
#endif

namespace glslrun {

template <class T>
class Span {
    // A container whose data() points at T: std::vector, std::array, ...
    template <class C>
    using if_container = std::enable_if_t<
        !std::is_same_v<std::remove_cv_t<std::remove_reference_t<C>>, Span> &&
        std::is_convertible_v<decltype(std::data(std::declval<C&>())), T*> &&
        std::is_convertible_v<decltype(std::size(std::declval<C&>())), std::size_t>>;

public:
    using element_type = T;
    using value_type = std::remove_cv_t<T>;
    using size_type = std::size_t;
    using iterator = T*;

    constexpr Span() noexcept = default;
    constexpr Span(T* data, std::size_t size) noexcept : data_(data), size_(size) {}
    template <std::size_t N>
    constexpr Span(T (&array)[N]) noexcept : data_(array), size_(N) {}
    template <class C, class = if_container<C>>
    constexpr Span(C&& container) noexcept : data_(std::data(container)), size_(std::size(container)) {}
    // Span<T> to Span<const T>.
    template <class U, class = std::enable_if_t<std::is_convertible_v<U*, T*> && !std::is_same_v<U, T>>>
    constexpr Span(const Span<U>& other) noexcept : data_(other.data()), size_(other.size()) {}
#if __cplusplus >= 202002L
    template <class U, std::size_t E, class = std::enable_if_t<std::is_convertible_v<U*, T*>>>
    constexpr Span(std::span<U, E> s) noexcept : data_(s.data()), size_(s.size()) {}
    constexpr operator std::span<T>() const noexcept { return {data_, size_}; }
#endif

    constexpr T* data() const noexcept { return data_; }
    constexpr std::size_t size() const noexcept { return size_; }
    constexpr bool empty() const noexcept { return size_ == 0; }
    constexpr T* begin() const noexcept { return data_; }
    constexpr T* end() const noexcept { return data_ + size_; }
    constexpr T& operator[](std::size_t i) const noexcept { return data_[i]; }

private:
    T* data_ = nullptr;
    std::size_t size_ = 0;
};

}  // namespace glslrun
