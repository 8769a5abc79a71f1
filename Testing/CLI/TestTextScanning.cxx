// The pre-checks' shared reading of text (Apps/IO/TextScanning.h): lines,
// words and whole-word numbers, with the cases the readers disagree on.
#include "TextScanning.h"

#include "CliErrors.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

using namespace cli;

TEST(TextScanning, LinesEndAtNewlinesAndKeepCarriageReturns)
{
  const std::string bytes = "ply\r\nformat ascii 1.0\n\nlast";
  TextCursor cursor(bytes);
  std::string line;
  bool ended = false;
  std::vector<std::string> lines;
  std::vector<bool> endings;
  while (cursor.NextLine(line, &ended))
  {
    lines.push_back(line);
    endings.push_back(ended);
  }
  EXPECT_EQ(lines, (std::vector<std::string>{ "ply\r", "format ascii 1.0", "", "last" }));
  EXPECT_EQ(endings, (std::vector<bool>{ true, true, true, false }));
  EXPECT_TRUE(cursor.AtEnd());
  EXPECT_FALSE(cursor.NextLine(line, &ended));
  EXPECT_TRUE(line.empty());
  EXPECT_FALSE(ended);
}

TEST(TextScanning, WordsSplitAtAnyWhiteSpaceAndLongWordsAreCut)
{
  EXPECT_EQ(WordsOf(" v\t1.5\v-2  3e1\r"), (std::vector<std::string>{ "v", "1.5", "-2", "3e1" }));
  EXPECT_TRUE(WordsOf(" \t\r ").empty());
  // Legacy VTK reads words into 256-byte buffers: a longer one is two.
  const std::string bytes = "SCALARS abcdefgh float\n";
  TextCursor cursor(bytes);
  EXPECT_EQ(cursor.Word(), "SCALARS");
  EXPECT_EQ(cursor.Word(5), "abcde");
  EXPECT_EQ(cursor.Word(5), "fgh");
  EXPECT_EQ(cursor.RestOfLine(), " float");
  EXPECT_EQ(cursor.Position(), bytes.size() - 1); // at the newline
  cursor.SkipToNextLine();
  EXPECT_TRUE(cursor.AtEnd());
  EXPECT_EQ(cursor.Word(), "");
}

TEST(TextScanning, SkipStopsAtTheEnd)
{
  const std::string bytes = "0123456789";
  TextCursor cursor(bytes, 4);
  cursor.Skip(3);
  EXPECT_EQ(cursor.Position(), 7u);
  cursor.Skip(100);
  EXPECT_EQ(cursor.Position(), bytes.size());
  EXPECT_TRUE(cursor.AtEnd());
}

TEST(TextScanning, IntegersAreWholeWordsOfDigits)
{
  long long value = -1;
  EXPECT_TRUE(ParseWholeInteger("42", value));
  EXPECT_EQ(value, 42);
  EXPECT_TRUE(ParseWholeInteger("-7", value));
  EXPECT_EQ(value, -7);
  EXPECT_TRUE(ParseWholeInteger("+3", value));
  EXPECT_EQ(value, 3);
  // What strtoll would take a prefix of, or read otherwise than the readers.
  for (const std::string& word :
    std::vector<std::string>{ "", "+", "-", "1e2", "0x10", "12a", "1.0", " 5", "5 ",
      std::string("1\0"
                  "2",
        3),
      "99999999999999999999" })
  {
    EXPECT_FALSE(ParseWholeInteger(word, value)) << "'" << word << "'";
  }
}

TEST(TextScanning, NumbersAreWholeWords)
{
  double value = 0.0;
  EXPECT_TRUE(ParseWholeNumber("-1.5e-3", value));
  EXPECT_EQ(value, -1.5e-3);
  EXPECT_TRUE(ParseWholeNumber("nan", value)); // a number to strtod: the checks decide
  for (const std::string& word : std::vector<std::string>{ "", "1.5x", "1,5", "--1",
         std::string("2\0"
                     "5",
           3) })
  {
    EXPECT_FALSE(ParseWholeNumber(word, value)) << "'" << word << "'";
  }
}

TEST(TextScanning, ExcerptsArePrintableAndShort)
{
  EXPECT_EQ(Excerpt("POINTS\x02\x1b[31m"), "POINTS??[31m");
  EXPECT_EQ(Excerpt(std::string(100, 'a')).size(), 40u);
  EXPECT_EQ(Lowercase("POLYGONS Offsets"), "polygons offsets");
}

// A whole file, a directory refused with the system's reason (its size, as
// a stream reports it, is no size to make room for).
TEST(TextScanning, ReadFileBytesReadsFilesAndRefusesDirectories)
{
  const std::string path = testing::TempDir() + "text_scanning_bytes.txt";
  std::string written(3 << 20, 'x'); // more than one chunk
  written[12345] = '\0';
  std::ofstream(path, std::ios::binary) << written;
  EXPECT_EQ(cli::ReadFileBytes(path), written);
  std::remove(path.c_str());
  try
  {
    cli::ReadFileBytes(testing::TempDir());
    ADD_FAILURE() << "a directory was read";
  }
  catch (const cli::RuntimeError& error)
  {
    EXPECT_NE(std::string(error.what()).find("Is a directory"), std::string::npos) << error.what();
  }
}
