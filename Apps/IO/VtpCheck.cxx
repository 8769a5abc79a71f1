#include "VtpCheck.h"

#include "CliErrors.h"
#include "TextScanning.h"
#include "VtkXmlData.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cli
{
namespace
{

// One piece of a PolyData file: its tag's counts and the span of its
// elements.
struct Piece
{
  std::size_t Begin = 0; ///< after its start tag
  std::size_t End = 0;   ///< its end tag (its start tag's end when empty)
  std::string Name;      ///< "piece 2", for messages
  std::uint64_t Points = 0;
  std::uint64_t Cells[4] = { 0, 0, 0, 0 }; ///< Verts, Lines, Strips, Polys
};

const char* const CellKinds[4] = { "Verts", "Lines", "Strips", "Polys" };

class PolyDataReading
{
public:
  PolyDataReading(const std::string& text, const VtkXmlData& data)
    : Text(text)
    , Data(data)
  {
  }

  int Pieces = 0;
  std::uint64_t FirstPiecePoints = 0;

  FileGeometry Read()
  {
    FileGeometry geometry;
    geometry.VertexOrderKept = true;
    geometry.Strips.Given = geometry.Lines.Given = geometry.Vertices.Given = true;
    const std::size_t dataset =
      FindXmlElement(this->Text, "PolyData", this->Data.XmlStart(), this->Data.XmlEnd());
    const std::string type = this->Data.Root().Attribute("type");
    if (type != "PolyData")
    {
      throw XmlUnreadable(type.empty()
          ? std::string("its VTKFile element has no type")
          : "its VTKFile type is '" + Excerpt(type) + "', not PolyData");
    }
    if (dataset == std::string::npos)
    {
      throw XmlUnreadable("it holds no PolyData element");
    }
    bool everyPieceHasNormals = true;
    int index = 0; // pieces numbered from 0, as VTK's reader numbers them
    for (std::size_t at = FindXmlElement(this->Text, "Piece", dataset, this->Data.XmlEnd());
         at != std::string::npos;
         at = FindXmlElement(this->Text, "Piece", at + 1, this->Data.XmlEnd()))
    {
      const Piece piece = this->PieceAt(at, index++);
      this->FirstPiecePoints = index == 1 ? piece.Points : this->FirstPiecePoints;
      this->Pieces = index;
      const auto base = geometry.VertexCount();
      this->ReadPoints(piece, geometry, everyPieceHasNormals);
      FileCells* cells[4] = { &geometry.Vertices, &geometry.Lines, &geometry.Strips, nullptr };
      for (int kind = 0; kind < 4; ++kind)
      {
        if (piece.Cells[kind] == 0)
        {
          continue;
        }
        if (cells[kind])
        {
          this->ReadCells(piece, kind, base, cells[kind]->Starts, cells[kind]->Corners);
        }
        else
        {
          this->ReadCells(piece, kind, base, geometry.FaceStarts, geometry.FaceCorners);
        }
      }
    }
    if (!everyPieceHasNormals)
    {
      geometry.Normals.clear();
    }
    return geometry;
  }

private:
  Piece PieceAt(std::size_t at, int index) const
  {
    const XmlTag tag = ParseXmlTag(this->Text, at);
    Piece piece;
    piece.Name = "piece " + std::to_string(index);
    if (tag.End == std::string::npos)
    {
      throw XmlUnreadable(piece.Name + "'s tag is cut short");
    }
    piece.Begin = tag.End + 1;
    piece.End =
      tag.Empty ? tag.End : std::min(this->Text.find("</Piece", piece.Begin), this->Data.XmlEnd());
    const char* const names[5] = { "NumberOfPoints", "NumberOfVerts", "NumberOfLines",
      "NumberOfStrips", "NumberOfPolys" };
    std::uint64_t* counts[5] = { &piece.Points, &piece.Cells[0], &piece.Cells[1], &piece.Cells[2],
      &piece.Cells[3] };
    for (int c = 0; c < 5; ++c)
    {
      const std::string value = tag.Attribute(names[c]);
      if (value.empty() && !tag.Has(names[c]))
      {
        if (c == 0)
        {
          throw XmlUnreadable(piece.Name + " has no NumberOfPoints");
        }
        continue; // none of these cells
      }
      if (!ParseXmlCount(value, *counts[c]))
      {
        throw XmlUnreadable(
          piece.Name + "'s " + names[c] + " is '" + Excerpt(value) + "', not a count");
      }
    }
    return piece;
  }

  // The DataArray tags in the element `name` of the piece: its start and end.
  std::pair<std::size_t, std::size_t> Section(const Piece& piece, const char* name) const
  {
    const std::size_t at = FindXmlElement(this->Text, name, piece.Begin, piece.End);
    if (at == std::string::npos)
    {
      return { std::string::npos, std::string::npos };
    }
    const std::size_t close = this->Text.find(std::string("</") + name, at);
    return { at, std::min(close, piece.End) };
  }

  // The DataArray of the section named `name` ("" for the first one).
  std::size_t ArrayIn(std::pair<std::size_t, std::size_t> section, const std::string& name) const
  {
    if (section.first == std::string::npos)
    {
      return std::string::npos;
    }
    for (std::size_t at = FindXmlElement(this->Text, "DataArray", section.first, section.second);
         at != std::string::npos;
         at = FindXmlElement(this->Text, "DataArray", at + 1, section.second))
    {
      if (name.empty() || ParseXmlTag(this->Text, at).Attribute("Name") == name)
      {
        return at;
      }
    }
    return std::string::npos;
  }

  void RequireThreeComponents(std::size_t at, const std::string& what) const
  {
    const XmlTag tag = ParseXmlTag(this->Text, at);
    if (!tag.Has("NumberOfComponents"))
    {
      throw XmlUnreadable(what + " has no NumberOfComponents, where 3 are wanted");
    }
    const std::string components = tag.Attribute("NumberOfComponents");
    if (components != "3")
    {
      throw XmlUnreadable(
        what + " has NumberOfComponents '" + Excerpt(components) + "', where 3 are wanted");
    }
  }

  void ReadPoints(const Piece& piece, FileGeometry& geometry, bool& hasNormals) const
  {
    if (piece.Points == 0)
    {
      return;
    }
    const std::size_t points = this->ArrayIn(this->Section(piece, "Points"), "");
    const std::string what = piece.Name + "'s Points";
    if (points == std::string::npos)
    {
      throw XmlUnreadable(piece.Name + " has points but no Points array");
    }
    this->RequireThreeComponents(points, what);
    this->Data.Numbers(points, 3 * piece.Points, what, geometry.Positions);
    // The point data's active normals, named by its Normals attribute.
    const auto pointData = this->Section(piece, "PointData");
    const std::string name = pointData.first == std::string::npos
      ? std::string()
      : ParseXmlTag(this->Text, pointData.first).Attribute("Normals");
    const std::size_t normals = name.empty() ? std::string::npos : this->ArrayIn(pointData, name);
    if (normals == std::string::npos || !hasNormals)
    {
      hasNormals = false;
      return;
    }
    const std::string normalsWhat = piece.Name + "'s normals '" + Excerpt(name) + "'";
    this->RequireThreeComponents(normals, normalsWhat);
    this->Data.Numbers(normals, 3 * piece.Points, normalsWhat, geometry.Normals);
  }

  // A piece's cells of one kind: each cell's corners are its connectivity
  // from the previous cell's end offset to its own, offset by `base`.
  void ReadCells(const Piece& piece, int kind, std::int64_t base, std::vector<std::int64_t>& starts,
    std::vector<std::int64_t>& corners) const
  {
    const std::string what = piece.Name + "'s " + CellKinds[kind];
    const auto section = this->Section(piece, CellKinds[kind]);
    const std::size_t connectivity = this->ArrayIn(section, "connectivity");
    const std::size_t offsets = this->ArrayIn(section, "offsets");
    if (connectivity == std::string::npos || offsets == std::string::npos)
    {
      throw XmlUnreadable(what + " lack a connectivity or an offsets array");
    }
    std::vector<std::int64_t> ends;
    this->Data.Integers(offsets, piece.Cells[kind], what + " offsets", ends);
    std::int64_t previous = 0;
    for (const std::int64_t end : ends)
    {
      if (end < previous)
      {
        this->Data.Fail(what + " offsets go back from " + std::to_string(previous) + " to " +
          std::to_string(end));
      }
      previous = end;
    }
    std::vector<std::int64_t> ids;
    this->Data.Integers(
      connectivity, static_cast<std::uint64_t>(previous), what + " connectivity", ids);
    for (const std::int64_t id : ids)
    {
      if (id < 0 || static_cast<std::uint64_t>(id) >= piece.Points)
      {
        this->Data.Fail(what + " name point " + std::to_string(id) + ", beyond the piece's " +
          std::to_string(piece.Points) + " points");
      }
    }
    std::int64_t start = 0;
    for (const std::int64_t end : ends)
    {
      for (std::int64_t c = start; c < end; ++c)
      {
        corners.push_back(base + ids[static_cast<std::size_t>(c)]);
      }
      starts.push_back(static_cast<std::int64_t>(corners.size()));
      start = end;
    }
  }

  const std::string& Text;
  const VtkXmlData& Data;
};

// The reader allocates for every piece's counts, all pieces together,
// before it reads an array: their sums must be what the file can hold (a
// point three values, a cell at least one, of a byte at least), checked on
// every piece before anything can stop the reading of the geometry.
void CheckPieceCounts(const std::string& text, const VtkXmlData& data)
{
  const char* const names[5] = { "NumberOfPoints", "NumberOfVerts", "NumberOfLines",
    "NumberOfStrips", "NumberOfPolys" };
  std::uint64_t sums[5] = { 0, 0, 0, 0, 0 };
  for (std::size_t at = FindXmlElement(text, "Piece", data.XmlStart(), data.XmlEnd());
       at != std::string::npos; at = FindXmlElement(text, "Piece", at + 1, data.XmlEnd()))
  {
    const XmlTag tag = ParseXmlTag(text, at);
    for (int c = 0; c < 5; ++c)
    {
      std::uint64_t count = 0;
      if (!ParseXmlCount(tag.Attribute(names[c]), count))
      {
        continue; // not a count: said when the geometry is read
      }
      const std::uint64_t most = c == 0 ? data.Limit() / 3 : data.Limit();
      sums[c] += count;
      if (count > most || sums[c] > most)
      {
        data.Fail(std::string(count > most ? "a piece declares " : "the pieces declare ") +
          names[c] + "=" + std::to_string(count > most ? count : sums[c]) +
          (count > most ? "" : " in all") + ", more than a file of " + std::to_string(text.size()) +
          " bytes can hold");
      }
    }
  }
}

} // namespace

VtpFacts CheckVtpFile(const std::string& path)
{
  const std::string text = ReadFileBytes(path);
  VtpFacts facts;
  const VtkXmlData data(text, "cannot read '" + path + "': VTK XML: ");
  if (!data.HasRoot())
  {
    facts.Unreadable = "it has no VTKFile element";
    return facts;
  }
  data.CheckDeclaredSizes();
  CheckPieceCounts(text, data);
  try
  {
    PolyDataReading reading(text, data);
    facts.Geometry = reading.Read();
    facts.Read = true;
    facts.Pieces = reading.Pieces;
    facts.FirstPiecePoints = reading.FirstPiecePoints;
  }
  catch (const XmlUnreadable& unreadable)
  {
    facts.Unreadable = unreadable.what();
  }
  return facts;
}

} // namespace cli
