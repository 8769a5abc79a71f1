// The VTK XML check reads a file's mesh by the format's rules
// (Apps/IO/VtpCheck.h, VtkXmlData.h), in every mode VTK writes, and
// vtkXMLPolyDataReader is held to it.
#include "CliErrors.h"
#include "FileGeometry.h"
#include "VtpCheck.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace
{

std::string TempPath(const std::string& name)
{
  return testing::TempDir() + "vtp_check_" + name;
}

// A square with a vertex cell, a line, a triangle, a strip and unit
// normals that differ per point.
vtkSmartPointer<vtkPolyData> SquareWithEveryCell()
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  const double corners[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0.25 }, { 0, 1, 0.5 } };
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (int i = 0; i < 4; ++i)
  {
    points->InsertNextPoint(corners[i]);
    normals->InsertNextTuple3(0.6 * (i % 2), 0.8 * (i % 2), 1.0 - (i % 2));
  }
  mesh->SetPoints(points);
  mesh->GetPointData()->SetNormals(normals);
  auto cells = [](std::vector<vtkIdType> ids) {
    auto array = vtkSmartPointer<vtkCellArray>::New();
    array->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    return array;
  };
  mesh->SetVerts(cells({ 3 }));
  mesh->SetLines(cells({ 0, 1 }));
  mesh->SetPolys(cells({ 0, 1, 2 }));
  mesh->SetStrips(cells({ 0, 1, 3, 2 }));
  return mesh;
}

struct Mode
{
  const char* Name;
  int DataMode;
  bool Encoded;
};

// A writer of `mesh` to `path` in `mode`, compressed by `compressor`; the
// caller sets the rest and writes.
vtkSmartPointer<vtkXMLPolyDataWriter> WriterOf(
  vtkPolyData* mesh, const std::string& path, const Mode& mode, int compressor)
{
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  writer->SetDataMode(mode.DataMode);
  writer->SetEncodeAppendedData(mode.Encoded);
  writer->SetCompressorType(compressor);
  return writer;
}

} // namespace

// Every byte order, header width, data mode and compressor, with blocks
// small enough to make several, in one piece and in two: the geometry read
// is the mesh written, piece after piece, and the reader's mesh is held to it.
TEST(VtpCheck, EveryModeVtkWritesIsReadAsWritten)
{
  vtkSmartPointer<vtkPolyData> mesh = SquareWithEveryCell();
  const Mode modes[] = { { "ascii", vtkXMLWriter::Ascii, false },
    { "binary", vtkXMLWriter::Binary, false }, { "raw", vtkXMLWriter::Appended, false },
    { "base64", vtkXMLWriter::Appended, true } };
  int files = 0;
  for (int pieces = 1; pieces <= 2; ++pieces)
  {
    for (const Mode& mode : modes)
    {
      for (int compressor = vtkXMLWriter::NONE; compressor <= vtkXMLWriter::LZMA; ++compressor)
      {
        for (const int header : { vtkXMLWriter::UInt32, vtkXMLWriter::UInt64 })
        {
          for (int order = vtkXMLWriter::BigEndian; order <= vtkXMLWriter::LittleEndian; ++order)
          {
            const std::string path = TempPath(std::string(mode.Name) + ".vtp");
            auto writer = WriterOf(mesh, path, mode, compressor);
            writer->SetBlockSize(16); // the points take 3 blocks
            writer->SetHeaderType(header);
            writer->SetByteOrder(order);
            writer->SetNumberOfPieces(pieces);
            ASSERT_EQ(writer->Write(), 1);
            const std::string where = path + " (" + mode.Name + ", compressor " +
              std::to_string(compressor) + ", header " + std::to_string(header) + ", order " +
              std::to_string(order) + ", " + std::to_string(pieces) + " pieces)";
            cli::VtpFacts facts;
            ASSERT_NO_THROW(facts = cli::CheckVtpFile(path)) << where;
            ASSERT_TRUE(facts.Read) << where << ": " << facts.Unreadable;
            const cli::FileGeometry& file = facts.Geometry;
            vtkNew<vtkXMLPolyDataReader> reader;
            reader->SetFileName(path.c_str());
            reader->Update();
            vtkPolyData* read = reader->GetOutput();
            // Each piece of the file holds the whole square (the writer's
            // input is not split), so the file holds it `pieces` times.
            ASSERT_EQ(file.VertexCount(), 4 * pieces) << where;
            EXPECT_EQ(file.FaceCount(), pieces) << where;
            EXPECT_EQ(file.Strips.Count(), pieces) << where;
            EXPECT_EQ(file.Lines.Count(), pieces) << where;
            EXPECT_EQ(file.Vertices.Count(), pieces) << where;
            for (int p = 0; p < pieces; ++p)
            {
              for (int i = 0; i < 4; ++i)
              {
                double point[3], normal[3];
                mesh->GetPoint(i, point);
                mesh->GetPointData()->GetNormals()->GetTuple(i, normal);
                for (int c = 0; c < 3; ++c)
                {
                  EXPECT_EQ(file.Positions[3 * (4 * p + i) + c], static_cast<float>(point[c]));
                  EXPECT_EQ(file.Normals[3 * (4 * p + i) + c], static_cast<float>(normal[c]));
                }
              }
              EXPECT_EQ(file.FaceCorners[3 * p + 2], 4 * p + 2) << where;
              EXPECT_EQ(file.Strips.Corners[4 * p + 3], 4 * p + 2) << where;
              EXPECT_EQ(file.Vertices.Corners[p], 4 * p + 3) << where;
            }
            EXPECT_NO_THROW(cli::RequireReadAsWritten(file, read, path, "vtkXMLPolyDataReader"))
              << where;
            // A reader that put a second piece's strip on the first piece's
            // points would be refused.
            read->GetStrips()->ReplaceCellAtId(pieces - 1, { 0, 1, 2, 3 });
            read->GetStrips()->Modified();
            EXPECT_THROW(cli::RequireReadAsWritten(file, read, path, "vtkXMLPolyDataReader"),
              cli::RuntimeError)
              << where;
            std::remove(path.c_str());
            ++files;
          }
        }
      }
    }
  }
  EXPECT_EQ(files, 2 * 4 * 4 * 2 * 2);
}

// What the rules cannot read is left to the reader, with the reason; what
// the reader would allocate or misread is refused before it runs.
TEST(VtpCheck, WhatTheRulesCannotReadIsSaid)
{
  const std::string head = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
                           "byte_order=\"LittleEndian\" header_type=\"UInt32\">\n<PolyData>\n";
  const std::string points =
    "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
    "0 0 0 1 0 0 1 1 0</DataArray></Points>\n";
  auto polys = [](const std::string& connectivity, const std::string& offsets) {
    return "<Polys><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
      connectivity + "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" +
      offsets + "</DataArray></Polys>\n";
  };
  auto check = [&](const std::string& piece, const std::string& body) {
    const std::string path = TempPath("made.vtp");
    std::ofstream(path) << head << piece << body << "</Piece>\n</PolyData>\n</VTKFile>\n";
    return cli::CheckVtpFile(path);
  };
  const std::string piece = "<Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\">\n";
  cli::VtpFacts facts = check(piece, points + polys("0 1 2", "3"));
  EXPECT_TRUE(facts.Read);
  EXPECT_EQ(facts.Geometry.FaceCorners, std::vector<std::int64_t>({ 0, 1, 2 }));
  facts =
    check("<Piece NumberOfPoints=\"-3\" NumberOfPolys=\"1\">\n", points + polys("0 1 2", "3"));
  EXPECT_FALSE(facts.Read);
  EXPECT_EQ(facts.Unreadable, "piece 0's NumberOfPoints is '-3', not a count");
  facts = check(piece, points + polys("0 1 2.5", "3"));
  EXPECT_EQ(
    facts.Unreadable, "piece 0's Polys connectivity holds '2.5', which is not a whole number");
  facts = check(piece, points + polys("0 1", "3"));
  EXPECT_EQ(facts.Unreadable,
    "piece 0's Polys connectivity holds 2 values, fewer than the 3 the piece needs");
  facts = check("<Piece NumberOfPolys=\"1\">\n", points + polys("0 1 2", "3"));
  EXPECT_EQ(facts.Unreadable, "piece 0 has no NumberOfPoints");
  EXPECT_THROW(check(piece, points + polys("0 1 3", "3")), cli::RuntimeError); // no point 3
  // More values than the piece's counts give an array: read as another mesh
  // by the reader, without a word.
  EXPECT_THROW(check(piece, points + polys("0 1 2 0", "3")), cli::RuntimeError);
  EXPECT_THROW(
    check("<Piece NumberOfPoints=\"2\" NumberOfPolys=\"1\">\n", points + polys("0 1 1", "3")),
    cli::RuntimeError);
  EXPECT_THROW(check("<Piece NumberOfPoints=\"3\" NumberOfPolys=\"2\">\n",
                 points + polys("0 1 2 0 1 2", "3 2")),
    cli::RuntimeError); // offsets going back
  // Every piece's counts are held to the file's size, even after a piece
  // the rules cannot read.
  EXPECT_THROW(check(piece +
                   "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" "
                   "format=\"ascii\">0 0 junk</DataArray></Points>\n" +
                   polys("0 1 2", "3") + "</Piece>\n<Piece NumberOfPoints=\"4000000000\">\n",
                 ""),
    cli::RuntimeError);
  try
  {
    check("<Piece NumberOfPoints=\"99999999999\" NumberOfPolys=\"1\">\n", points);
    ADD_FAILURE() << "a piece declaring more points than the file holds was let through";
  }
  catch (const cli::RuntimeError& error)
  {
    EXPECT_NE(std::string(error.what()).find("more than a file of"), std::string::npos)
      << error.what();
  }
  std::remove(TempPath("made.vtp").c_str());
}

// Each array holds as many values as its piece's counts give it: a type
// relabelled narrower (Int64 connectivity marked Int32) would otherwise be
// read, by the reader too, as another mesh without a word.
TEST(VtpCheck, AnArrayHoldsWhatItsPieceGivesIt)
{
  vtkSmartPointer<vtkPolyData> mesh = SquareWithEveryCell();
  const Mode modes[] = { { "binary", vtkXMLWriter::Binary, false },
    { "raw", vtkXMLWriter::Appended, false }, { "base64", vtkXMLWriter::Appended, true } };
  for (const Mode& mode : modes)
  {
    for (const int compressor : { vtkXMLWriter::NONE, vtkXMLWriter::ZLIB })
    {
      const std::string path = TempPath(std::string("relabelled_") + mode.Name + ".vtp");
      ASSERT_EQ(WriterOf(mesh, path, mode, compressor)->Write(), 1);
      ASSERT_TRUE(cli::CheckVtpFile(path).Read) << path;
      std::string text;
      {
        std::ifstream in(path, std::ios::binary);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      }
      const std::string wide = "type=\"Int64\" Name=\"connectivity\"";
      const std::size_t at = text.find(wide);
      ASSERT_NE(at, std::string::npos) << path;
      text.replace(at, wide.size(), "type=\"Int32\" Name=\"connectivity\"");
      std::ofstream(path, std::ios::binary) << text;
      try
      {
        cli::CheckVtpFile(path);
        ADD_FAILURE() << mode.Name << ", compressor " << compressor
                      << ": a relabelled connectivity array was let through";
      }
      catch (const cli::RuntimeError& error)
      {
        EXPECT_NE(std::string(error.what()).find("connectivity holds"), std::string::npos)
          << error.what();
      }
      std::remove(path.c_str());
    }
  }
}

// A block size larger than the data, as SetBlockSize allows: only the last
// block's size is used, and the file is read (it was refused as declaring
// the block size).
TEST(VtpCheck, OneBlockLargerThanItsDataIsRead)
{
  vtkSmartPointer<vtkPolyData> mesh = SquareWithEveryCell();
  const std::string path = TempPath("big_block.vtp");
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  writer->SetCompressorTypeToZLib();
  writer->SetBlockSize(1 << 27);
  ASSERT_EQ(writer->Write(), 1);
  cli::VtpFacts facts;
  ASSERT_NO_THROW(facts = cli::CheckVtpFile(path));
  EXPECT_TRUE(facts.Read) << facts.Unreadable;
  EXPECT_EQ(facts.Geometry.VertexCount(), 4);
  std::remove(path.c_str());
}
