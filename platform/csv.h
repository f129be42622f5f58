#pragma once
// Reading CSV (RFC 4180) as spreadsheets and LMS exports write it: quoted
// fields may hold commas, doubled quotes and line breaks; lines end in LF or
// CRLF; a UTF-8 byte-order mark at the start is dropped. The one reader of
// the program (rosters today), so a quoted newline never splits a record.
#include <string>
#include <string_view>
#include <vector>

namespace fl::platform {

struct CsvRecord {
    int line = 0; // where the record starts, from 1 (a record may span lines)
    std::vector<std::string> fields;
};

struct CsvText {
    std::vector<CsvRecord> records; // blank lines are not records
    // Set when a quoted field is never closed: what is wrong and on which
    // line it started; the records before it are kept.
    std::string error;
    int errorLine = 0;
};

CsvText readCsv(std::string_view text);

} // namespace fl::platform
