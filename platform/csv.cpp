#include "platform/csv.h"

namespace fl::platform {

CsvText readCsv(std::string_view text) {
    CsvText result;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    CsvRecord record;
    std::string field;
    bool quoted = false;    // inside a quoted field
    bool fieldSeen = false; // the record has a character or a separator
    int line = 1;
    record.line = 1;
    auto endRecord = [&] {
        if (fieldSeen) {
            record.fields.push_back(std::move(field));
            result.records.push_back(std::move(record));
        }
        record = {};
        field.clear();
        fieldSeen = false;
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') ++line;
        if (quoted) {
            if (c != '"') {
                field += c;
            } else if (i + 1 < text.size() && text[i + 1] == '"') {
                field += '"';
                ++i;
            } else {
                quoted = false;
            }
            continue;
        }
        if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') continue;
        if (c == '\n' || c == '\r') {
            endRecord();
            record.line = line + (c == '\r' ? 1 : 0);
            if (c == '\r') ++line;
            continue;
        }
        if (!fieldSeen) record.line = line;
        fieldSeen = true;
        if (c == '"' && field.empty()) {
            quoted = true;
        } else if (c == ',') {
            record.fields.push_back(std::move(field));
            field.clear();
        } else {
            field += c;
        }
    }
    if (quoted) {
        result.error = "a quoted field is never closed (a \" is missing)";
        result.errorLine = record.line;
        return result;
    }
    endRecord();
    return result;
}

} // namespace fl::platform
