#pragma once
// Errors are values: every operation a user can trigger returns either its result or an Error whose
// message says what to fix (file, line, column or parameter). Nothing user-facing throws.
#include <QString>
#include <optional>
#include <utility>
#include <variant>

namespace athlos {

struct Error {
    QString message;
};

template <class T>
class [[nodiscard]] Expected {
public:
    Expected(T value) : v_(std::move(value)) {}
    Expected(Error error) : v_(std::move(error)) {}

    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<0>(v_); }
    const T& value() const& { return std::get<0>(v_); }
    T&& value() && { return std::get<0>(std::move(v_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const { return std::get<1>(v_); }
    const QString& message() const { return error().message; }

private:
    std::variant<T, Error> v_;
};

// Success or an Error, for operations without a result.
class [[nodiscard]] Status {
public:
    Status() = default;
    Status(Error error) : error_(std::move(error)) {}
    static Status success() { return {}; }

    bool ok() const { return !error_.has_value(); }
    explicit operator bool() const { return ok(); }
    const Error& error() const { return *error_; }
    const QString& message() const { return error_->message; }

private:
    std::optional<Error> error_;
};

inline Error makeError(QString message) { return Error{std::move(message)}; }

// The outcome of an Expected without its value.
template <class T>
Status statusOf(const Expected<T>& expected) {
    return expected ? Status() : Status(expected.error());
}

}  // namespace athlos
