#include "core/io/CsvReader.h"

#include <QFileInfo>
#include <cmath>
#include <cstring>
#include <limits>

namespace athlos {

Status MappedFile::open(const QString& path) {
    file_.setFileName(path);
    if (!file_.open(QIODevice::ReadOnly))
        return makeError(QStringLiteral("%1: cannot open: %2").arg(path, file_.errorString()));
    size_ = file_.size();
    if (size_ == 0) {
        begin_ = "";
        return {};
    }
    if (uchar* map = file_.map(0, size_)) {
        begin_ = reinterpret_cast<const char*>(map);
        return {};
    }
    // Not mappable (a pipe, some network file systems): read it instead.
    fallback_ = file_.readAll();
    if (fallback_.size() != size_)
        return makeError(QStringLiteral("%1: cannot read: %2").arg(path, file_.errorString()));
    begin_ = fallback_.constData();
    return {};
}

CsvReader::CsvReader(const char* begin, const char* end) : begin_(begin), end_(end), p_(begin) {
    if (end_ - p_ >= 3 && std::memcmp(p_, "\xEF\xBB\xBF", 3) == 0) p_ += 3;
}

const char* CsvReader::lineEnd(const char* from) const {
    const void* nl = std::memchr(from, '\n', static_cast<size_t>(end_ - from));
    return nl ? static_cast<const char*>(nl) : end_;
}

const char* CsvReader::fieldEnd(const char* from) const {
    const char* q = from;
    while (q < end_ && *q == ' ') ++q;
    if (q < end_ && *q == '"') {
        // A quoted cell may hold the delimiter; "" is an escaped quote. It never spans lines.
        for (++q; q < end_ && *q != '\n'; ++q) {
            if (*q != '"') continue;
            if (q + 1 < end_ && q[1] == '"') {
                ++q;
                continue;
            }
            ++q;
            break;
        }
    }
    while (q < end_ && *q != delim_ && *q != '\n' && *q != '\r') ++q;
    return q;
}

void CsvReader::extract(const char* b, const char* e, std::string& out) const {
    while (b < e && (*b == ' ' || (*b == '\t' && delim_ != '\t'))) ++b;
    while (e > b && (e[-1] == ' ' || (e[-1] == '\t' && delim_ != '\t'))) --e;
    out.clear();
    if (e - b >= 2 && *b == '"' && e[-1] == '"') {
        for (const char* q = b + 1; q < e - 1; ++q) {
            out.push_back(*q);
            if (*q == '"' && q + 1 < e - 1 && q[1] == '"') ++q;
        }
    } else {
        out.assign(b, e);
    }
}

bool CsvReader::nextRecord() {
    while (p_ < end_) {
        const char* eol = nullptr;
        const char c = *p_;
        ++line_;
        lineStart_ = p_;
        field_ = 0;
        if (c == '#' || c == '\n' || c == '\r' || c == ' ' || c == '\t') {
            eol = lineEnd(p_);
            bool blank = c != '#';
            for (const char* q = p_; blank && q < eol; ++q) blank = *q == ' ' || *q == '\t' || *q == '\r';
            if (c == '#' || blank) {
                p_ = eol < end_ ? eol + 1 : end_;
                continue;
            }
        }
        return true;
    }
    return false;
}

bool CsvReader::readHeader(QStringList& cells) {
    cells.clear();
    if (!nextRecord()) return false;
    if (delim_ == 0) {
        int counts[3] = {0, 0, 0};
        const char candidates[3] = {',', ';', '\t'};
        bool quoted = false;
        for (const char *q = p_, *eol = lineEnd(p_); q < eol; ++q) {
            if (*q == '"') quoted = !quoted;
            for (int i = 0; i < 3 && !quoted; ++i) counts[i] += *q == candidates[i];
        }
        int best = 0;
        for (int i = 1; i < 3; ++i)
            if (counts[i] > counts[best]) best = i;
        delim_ = candidates[best];
    }
    std::string cell;
    while (text(cell)) cells << QString::fromUtf8(cell.data(), qsizetype(cell.size()));
    finishRecord();
    return true;
}

bool CsvReader::text(std::string& out) {
    if (field_++ > 0) {
        if (p_ == end_ || *p_ != delim_) return false;
        ++p_;
    }
    fieldBegin_ = p_;
    p_ = fieldEnd(p_);
    extract(fieldBegin_, p_, out);
    return true;
}

CsvReader::Field CsvReader::slowNumber(double& value) {
    value = std::numeric_limits<double>::quiet_NaN();
    std::string cell;
    p_ = fieldEnd(fieldBegin_);
    extract(fieldBegin_, p_, cell);
    if (cell.empty()) return Field::Empty;
    // Forms from spreadsheets and other locales: "+1.5", and "1,5" where ',' is not the delimiter.
    if (cell.front() == '+') cell.erase(0, 1);
    if (delim_ != ',' && cell.find(',') != std::string::npos && cell.find('.') == std::string::npos)
        for (char& ch : cell)
            if (ch == ',') ch = '.';
    const char* b = cell.data();
    const char* e = b + cell.size();
    const auto [q, ec] = std::from_chars(b, e, value);
    if (ec != std::errc() || q != e) {
        value = std::numeric_limits<double>::quiet_NaN();
        return Field::Invalid;
    }
    return Field::Number;
}

bool CsvReader::finishRecord() {
    if (p_ < end_ && *p_ == delim_) return false;
    const char* eol = lineEnd(p_);
    p_ = eol < end_ ? eol + 1 : end_;
    return true;
}

int CsvReader::fieldsOnLine() const {
    if (!lineStart_) return 0;
    int n = 1;
    for (const char* q = lineStart_; (q = fieldEnd(q)) < end_ && *q == delim_; ++q) ++n;
    return n;
}

std::string_view CsvReader::lastField() const {
    if (!fieldBegin_) return {};
    const char* e = fieldEnd(fieldBegin_);
    return {fieldBegin_, static_cast<size_t>(e - fieldBegin_)};
}

}  // namespace athlos
