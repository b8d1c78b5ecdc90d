// The small helpers of host/base/ that every report goes through: JSON text (base/json.h).
#include "base/json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

TEST(Json, StringsEscapeQuotesBackslashesAndControlCharacters) {
    EXPECT_EQ(jsonString("plain"), "\"plain\"");
    EXPECT_EQ(jsonString("a\"b\\c"), "\"a\\\"b\\\\c\"");
    EXPECT_EQ(jsonString(std::string("tab\there\nnul\0!", 14)),
              "\"tab\\u0009here\\u000anul\\u0000!\"");
    EXPECT_EQ(jsonString("caf\xC3\xA9"), "\"caf\xC3\xA9\""); // UTF-8 passes as it is
}

TEST(Json, NumbersHaveTheirDigitsAndNonFiniteValuesAreNull) {
    EXPECT_EQ(jsonNumber(1.23456), "1.235");
    EXPECT_EQ(jsonNumber(0.1f, 9), "0.100000001");
    EXPECT_EQ(jsonNumber(0.1, 17), "0.10000000000000001");
    EXPECT_EQ(jsonNumber(std::numeric_limits<double>::infinity(), 9), "null");
    EXPECT_EQ(jsonNumber(std::nan(""), 17), "null");
    struct Vector {
        float x, y, z;
    };
    EXPECT_EQ(jsonTriple(Vector{1.0f, -2.5f, NAN}, 9), "[1, -2.5, null]");
}
