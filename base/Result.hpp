#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace speculum::base {

// A recoverable failure with a message meant for the user ("nodes[2].mirror.size: expected 2 numbers").
struct Error {
    std::string message;
};

// Value-or-error for recoverable failures (files, user input). Programmer errors are assertions instead.
template <typename T>
class Result {
public:
    Result(T value)
        : m_state(std::move(value)) {}
    Result(Error error)
        : m_state(std::move(error)) {}

    bool ok() const { return std::holds_alternative<T>(m_state); }
    explicit operator bool() const { return ok(); }

    T& value() & {
        assert(ok() && "Result::value(): holds an error");
        return std::get<T>(m_state);
    }
    const T& value() const& {
        assert(ok() && "Result::value(): holds an error");
        return std::get<T>(m_state);
    }
    T&& value() && {
        assert(ok() && "Result::value(): holds an error");
        return std::get<T>(std::move(m_state));
    }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const std::string& error() const {
        assert(!ok() && "Result::error(): holds a value");
        return std::get<Error>(m_state).message;
    }

private:
    std::variant<T, Error> m_state;
};

// For operations that return nothing on success.
struct Done {};
using Status = Result<Done>;

} // namespace speculum::base
