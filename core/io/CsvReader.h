#pragma once
// A fast CSV tokenizer over a memory-mapped file, for the CSV-based importers.
//
// It knows lines, fields and numbers, nothing about columns or kinds. Numbers are parsed in place
// with std::from_chars (no copy, no locale); only unusual cells (quotes, spaces, '+', decimal comma)
// take a slower path. Lines end in LF or CRLF; blank lines, whitespace-only lines and lines
// starting with '#' are skipped; a UTF-8 byte-order mark is ignored. Quoted cells may contain the
// delimiter but not a line break. Line numbers are physical, 1-based (a header in the first line
// is line 1), so error messages point at what an editor shows.
#include "core/util/Expected.h"

#include <QFile>
#include <QString>
#include <QStringList>
#include <charconv>
#include <string>
#include <string_view>

namespace athlos {

// Read-only view of a whole file: memory-mapped when possible, read into memory otherwise.
class MappedFile {
public:
    Status open(const QString& path);
    const char* begin() const { return begin_; }
    const char* end() const { return begin_ + size_; }
    qint64 size() const { return size_; }

private:
    QFile file_;
    QByteArray fallback_;
    const char* begin_ = nullptr;
    qint64 size_ = 0;
};

class CsvReader {
public:
    enum class Field { Number, Empty, Invalid, Missing };

    CsvReader(const char* begin, const char* end);

    // Reads the next record as header cells (trimmed, unquoted). The first call detects the
    // delimiter from the line: the most frequent of ',', ';' and tab outside quotes (',' if none).
    bool readHeader(QStringList& cells);
    char delimiter() const { return delim_; }

    // Moves to the next data record (skipping blank and comment lines); false at the end.
    bool nextRecord();
    // The next field of the current record as a number. Empty cells give Empty (value NaN);
    // Missing means the line has no more fields.
    Field number(double& value) {
        if (field_++ > 0) {
            if (p_ == end_ || *p_ != delim_) return Field::Missing;
            ++p_;
        }
        fieldBegin_ = p_;
        const auto [q, ec] = std::from_chars(p_, end_, value);
        if (ec == std::errc() && isFieldEnd(q)) [[likely]] {
            p_ = q;
            return Field::Number;
        }
        return slowNumber(value);
    }
    // The next field as text (trimmed, unquoted, "" unescaped); false if the line has no more fields.
    bool text(std::string& out);
    // After the expected number of fields: true and on to the next line if the line ends here,
    // false if it has more fields.
    bool finishRecord();

    long long line() const { return line_; }
    int fieldIndex() const { return field_; }      // 1-based index of the last field read
    int fieldsOnLine() const;                      // fields of the current line (for messages)
    std::string_view lastField() const;            // raw text of the last field (for messages)
    qint64 offset() const { return p_ - begin_; }  // bytes consumed (for progress)

private:
    bool isFieldEnd(const char* q) const { return q == end_ || *q == delim_ || *q == '\n' || *q == '\r'; }
    Field slowNumber(double& value);
    const char* fieldEnd(const char* from) const;  // quote-aware end of the field starting at from
    const char* lineEnd(const char* from) const;   // position of '\n' (or end)
    void extract(const char* b, const char* e, std::string& out) const;  // trim, unquote

    const char* begin_;
    const char* end_;
    const char* p_;
    const char* lineStart_ = nullptr;
    const char* fieldBegin_ = nullptr;
    long long line_ = 0;
    int field_ = 0;
    char delim_ = 0;
};

}  // namespace athlos
