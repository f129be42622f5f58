// The one CSV reader: what spreadsheets and LMS exports write reads back as
// it was meant, and hostile text ends with a located error, never a crash.
#include "platform/csv.h"

#include <gtest/gtest.h>

#include <random>

using fl::platform::readCsv;

TEST(Csv, PlainFieldsAndLineNumbers) {
    const auto t = readCsv("id,name\nalice,Alice\n\nbob,Bob\n");
    ASSERT_TRUE(t.error.empty());
    ASSERT_EQ(t.records.size(), 3u);
    EXPECT_EQ(t.records[1].fields, (std::vector<std::string>{"alice", "Alice"}));
    EXPECT_EQ(t.records[2].line, 4); // the blank line 3 is no record
}

TEST(Csv, AQuotedNewlineStaysInItsField) {
    const auto t = readCsv("id,name\r\nalice,\"Alice\r\nof Wonderland\"\r\nbob,Bob\r\n");
    ASSERT_TRUE(t.error.empty());
    ASSERT_EQ(t.records.size(), 3u);
    EXPECT_EQ(t.records[1].fields[1], "Alice\r\nof Wonderland");
    EXPECT_EQ(t.records[2].fields[0], "bob");
    EXPECT_EQ(t.records[2].line, 4);
}

TEST(Csv, DoubledQuotesCommasAndEmptyFields) {
    const auto t = readCsv("\"a,b\",\"say \"\"hi\"\"\",,\n");
    ASSERT_EQ(t.records.size(), 1u);
    EXPECT_EQ(t.records[0].fields, (std::vector<std::string>{"a,b", "say \"hi\"", "", ""}));
}

TEST(Csv, AByteOrderMarkIsDropped) {
    const auto t = readCsv("\xEF\xBB\xBFid,name\nalice,A");
    ASSERT_EQ(t.records.size(), 2u);
    EXPECT_EQ(t.records[0].fields[0], "id");
    EXPECT_EQ(t.records[1].fields[1], "A"); // no newline at the end
}

TEST(Csv, AnUnclosedQuoteIsLocated) {
    const auto t = readCsv("id\nalice\n\"bob\ncarol\n");
    EXPECT_FALSE(t.error.empty());
    EXPECT_EQ(t.errorLine, 3);
    ASSERT_EQ(t.records.size(), 2u); // what came before is kept
}

TEST(Csv, WriteThenReadIsTheIdentity) {
    // Property: any table of fields, quoted as RFC 4180 says, reads back.
    std::mt19937 random(7);
    const std::string alphabet = "ab ,\"\r\n\t;=\xC3\xA9";
    for (int round = 0; round < 300; ++round) {
        std::vector<std::vector<std::string>> table(1 + random() % 4);
        std::string text;
        for (auto& row : table) {
            row.resize(1 + random() % 4);
            for (std::size_t c = 0; c < row.size(); ++c) {
                for (unsigned k = random() % 6; k > 0; --k)
                    row[c] += alphabet[random() % alphabet.size()];
                if (c) text += ',';
                text += '"';
                for (char ch : row[c])
                    text += ch == '"' ? std::string("\"\"") : std::string(1, ch);
                text += '"';
            }
            text += "\r\n";
        }
        const auto t = readCsv(text);
        ASSERT_TRUE(t.error.empty()) << text;
        ASSERT_EQ(t.records.size(), table.size()) << text;
        for (std::size_t r = 0; r < table.size(); ++r)
            EXPECT_EQ(t.records[r].fields, table[r]) << text;
    }
}
