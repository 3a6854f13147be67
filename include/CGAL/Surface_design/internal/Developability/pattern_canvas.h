// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A cutting pattern as a list of layers of paths and labels, written as SVG (one drawing of all
// sheets side by side) or as PDF (one page per sheet; written directly, no library needed).

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_PATTERN_CANVAS_H
#define CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_PATTERN_CANVAS_H

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

/// Colours are "#rrggbb" or "none"; lengths in mm; dash: "on,off,..." in mm (empty: solid).
struct Pattern_style
{
  std::string fill = "none", stroke = "none";
  double width = 0.;
  std::string dash;
};

/// Polylines in mm on the drawing of all sheets, y pointing down (as in SVG).
struct Pattern_path
{
  std::vector<std::vector<Eigen::Vector2d>> parts;
  bool closed = false;
  bool own_style = false; ///< draw with `style` instead of the layer's
  Pattern_style style;
};

struct Pattern_text
{
  Eigen::Vector2d at; ///< the centre of the label, or the start of its baseline's middle if not centred
  std::string text;
};

struct Pattern_layer
{
  std::string id;
  Pattern_style style;      ///< of the paths, and `fill` the colour of the texts
  bool round_joins = false;
  bool rectangles = false;  ///< every path is one axis-aligned rectangle (its four corners)
  double font_size = 0.;    ///< mm
  bool bold = false, centered = true;
  std::vector<Pattern_path> paths;
  std::vector<Pattern_text> texts;
};

struct Pattern_scene
{
  double sheet_width = 0., sheet_height = 0., sheet_gap = 0.; ///< mm
  std::size_t sheets = 0;
  std::string title;
  std::vector<Pattern_layer> layers;
};

namespace pattern_canvas_detail {

inline std::string xml_escaped(const std::string& s)
{
  std::string out;
  for(char c : s)
  {
    if(c == '<')
      out += "&lt;";
    else if(c == '>')
      out += "&gt;";
    else if(c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

inline void svg_style(std::ostream& os, const Pattern_style& s)
{
  os << " fill=\"" << s.fill << "\" stroke=\"" << s.stroke << '"';
  if(s.stroke != "none")
    os << " stroke-width=\"" << s.width << '"';
  if(!s.dash.empty())
    os << " stroke-dasharray=\"" << s.dash << '"';
}

// "#rrggbb" -> "r g b" in [0, 1]
inline std::string pdf_colour(const std::string& hex)
{
  unsigned r = 0, g = 0, b = 0;
  if(hex.size() == 7)
    std::sscanf(hex.c_str() + 1, "%2x%2x%2x", &r, &g, &b);
  std::ostringstream s;
  s << std::setprecision(4) << r / 255. << ' ' << g / 255. << ' ' << b / 255.;
  return s.str();
}

inline std::string pdf_string(const std::string& text)
{
  std::string out = "(";
  for(char c : text)
  {
    if(c == '(' || c == ')' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + ")";
}

// Width of `text` in Helvetica in units of the font size (the standard metrics of the characters
// a pattern's centred labels use, the same in Helvetica-Bold; others as a digit).
inline double helvetica_width(const std::string& text)
{
  double w = 0.;
  for(char c : text)
  {
    if(c >= '0' && c <= '9')
      w += 556.;
    else if(c == 'P')
      w += 667.;
    else if(c == ' ' || c == '.' || c == ',')
      w += 278.;
    else if(c == '=')
      w += 584.;
    else
      w += 556.;
  }
  return w / 1000.;
}

} // namespace pattern_canvas_detail

/// The scene as one SVG drawing, sheets side by side, in mm.
inline void write_scene_svg(std::ostream& os, const Pattern_scene& scene)
{
  using namespace pattern_canvas_detail;
  const double total_width = double(scene.sheets) * (scene.sheet_width + scene.sheet_gap) - scene.sheet_gap;
  const double H = scene.sheet_height;
  os << std::fixed << std::setprecision(3);
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << total_width << "mm\" height=\"" << H
     << "mm\" viewBox=\"0 0 " << total_width << ' ' << H << "\">\n"
     << "<title>" << xml_escaped(scene.title) << "</title>\n";
  for(const Pattern_layer& layer : scene.layers)
  {
    os << "<g id=\"" << layer.id << '"';
    svg_style(os, layer.style);
    if(layer.round_joins)
      os << " stroke-linejoin=\"round\"";
    if(layer.font_size > 0.)
      os << " font-family=\"sans-serif\" font-size=\"" << std::setprecision(1) << layer.font_size
         << std::setprecision(3) << '"' << (layer.bold ? " font-weight=\"bold\"" : "")
         << (layer.centered ? " text-anchor=\"middle\" dominant-baseline=\"middle\"" : "");
    os << ">\n";
    for(const Pattern_path& path : layer.paths)
    {
      if(layer.rectangles)
      {
        const Eigen::Vector2d a = path.parts.front()[0], c = path.parts.front()[2];
        os << "<rect x=\"" << (std::min)(a.x(), c.x()) << "\" y=\"" << (std::min)(a.y(), c.y()) << "\" width=\""
           << std::abs(c.x() - a.x()) << "\" height=\"" << std::abs(c.y() - a.y()) << "\"/>\n";
        continue;
      }
      os << "<path";
      if(path.own_style)
        svg_style(os, path.style);
      os << " d=\"";
      bool first_part = true;
      for(const std::vector<Eigen::Vector2d>& part : path.parts)
      {
        for(std::size_t i = 0; i < part.size(); ++i)
          os << (i == 0 ? (first_part ? "M" : " M") : " L") << part[i].x() << ',' << part[i].y();
        if(path.closed)
          os << " Z";
        first_part = false;
      }
      os << "\"/>\n";
    }
    for(const Pattern_text& t : layer.texts)
      os << "<text x=\"" << t.at.x() << "\" y=\"" << t.at.y() << "\">" << xml_escaped(t.text) << "</text>\n";
    os << "</g>\n";
  }
  os << "</svg>\n";
}

/// The scene as a PDF document of one page per sheet, each the sheet's size, in the same layers,
/// colours and line styles (PDF 1.4, the standard Helvetica fonts, no compression).
inline void write_scene_pdf(std::ostream& os, const Pattern_scene& scene)
{
  using namespace pattern_canvas_detail;
  const double pt = 72. / 25.4; // points per mm
  const double period = scene.sheet_width + scene.sheet_gap, H = scene.sheet_height;
  const std::size_t pages = (std::max)(scene.sheets, std::size_t(1));
  auto page_of = [&](double x) {
    const double k = std::floor((x + 0.5 * scene.sheet_gap) / period);
    return std::size_t((std::max)(0., (std::min)(double(pages - 1), k)));
  };
  std::vector<std::ostringstream> content(pages);
  for(std::ostringstream& c : content)
    c << std::fixed << std::setprecision(3);
  auto X = [&](std::size_t page, double x) { return (x - double(page) * period) * pt; };
  auto Y = [&](double y) { return (H - y) * pt; };
  auto set_style = [&](std::ostream& c, const Pattern_style& s, bool round_joins) {
    if(s.fill != "none")
      c << pdf_colour(s.fill) << " rg\n";
    if(s.stroke != "none")
    {
      c << pdf_colour(s.stroke) << " RG " << s.width * pt << " w " << (round_joins ? 1 : 0) << " j [";
      std::string dash = s.dash;
      for(char& ch : dash)
        if(ch == ',')
          ch = ' ';
      std::istringstream in(dash);
      double on;
      while(in >> on)
        c << ' ' << on * pt;
      c << " ] 0 d\n";
    }
  };
  auto paint = [](const Pattern_style& s, bool closed) {
    const bool fill = s.fill != "none" && closed, stroke = s.stroke != "none";
    return fill && stroke ? "B" : (fill ? "f" : (stroke ? "S" : "n"));
  };
  for(const Pattern_layer& layer : scene.layers)
  {
    for(const Pattern_path& path : layer.paths)
    {
      // the parts of the path on each page, painted together
      const Pattern_style& style = path.own_style ? path.style : layer.style;
      const bool closed = path.closed || layer.rectangles;
      std::vector<std::vector<const std::vector<Eigen::Vector2d>*>> on_page(pages);
      for(const std::vector<Eigen::Vector2d>& part : path.parts)
        if(!part.empty())
          on_page[page_of(part.front().x())].push_back(&part);
      for(std::size_t page = 0; page < pages; ++page)
      {
        if(on_page[page].empty())
          continue;
        std::ostringstream& c = content[page];
        c << "q\n";
        set_style(c, style, layer.round_joins);
        for(const std::vector<Eigen::Vector2d>* part : on_page[page])
        {
          for(std::size_t i = 0; i < part->size(); ++i)
            c << X(page, (*part)[i].x()) << ' ' << Y((*part)[i].y()) << (i == 0 ? " m\n" : " l\n");
          if(closed)
            c << "h\n";
        }
        c << paint(style, closed) << "\nQ\n";
      }
    }
    for(const Pattern_text& t : layer.texts)
    {
      const std::size_t page = page_of(t.at.x());
      std::ostringstream& c = content[page];
      const double size = layer.font_size * pt;
      double x = X(page, t.at.x()), y = Y(t.at.y());
      if(layer.centered)
      {
        x -= 0.5 * helvetica_width(t.text) * size;
        y -= 0.36 * size; // the middle of the digits' height on the centre
      }
      c << "BT " << pdf_colour(layer.style.fill) << " rg /" << (layer.bold ? "F2" : "F1") << ' ' << size << " Tf " << x
        << ' ' << y << " Td " << pdf_string(t.text) << " Tj ET\n";
    }
  }

  // objects: 1 catalog, 2 pages, 3-4 fonts, 5 info, then per page its page and its content
  std::ostringstream out;
  out << std::fixed << std::setprecision(3);
  std::vector<std::size_t> offset;
  auto object = [&](const std::string& body) {
    offset.push_back(std::size_t(out.tellp()));
    out << offset.size() << " 0 obj\n" << body << "\nendobj\n";
  };
  out << "%PDF-1.4\n%\xE2\xE3\xCF\xD3\n";
  object("<< /Type /Catalog /Pages 2 0 R >>");
  {
    std::ostringstream kids;
    for(std::size_t k = 0; k < pages; ++k)
      kids << (k ? " " : "") << 6 + 2 * k << " 0 R";
    object("<< /Type /Pages /Kids [" + kids.str() + "] /Count " + std::to_string(pages) + " >>");
  }
  object("<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>");
  object("<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica-Bold /Encoding /WinAnsiEncoding >>");
  object("<< /Title " + pdf_string(scene.title) + " /Producer (CGAL Surface Design) >>");
  for(std::size_t k = 0; k < pages; ++k)
  {
    std::ostringstream page;
    page << std::fixed << std::setprecision(3) << "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 "
         << scene.sheet_width * pt << ' ' << H * pt << "] /Resources << /Font << /F1 3 0 R /F2 4 0 R >> >> /Contents "
         << 7 + 2 * k << " 0 R >>";
    object(page.str());
    const std::string stream = content[k].str();
    object("<< /Length " + std::to_string(stream.size()) + " >>\nstream\n" + stream + "endstream");
  }
  const std::size_t xref = std::size_t(out.tellp());
  out << "xref\n0 " << offset.size() + 1 << "\n0000000000 65535 f \n";
  for(std::size_t o : offset)
  {
    char entry[32];
    std::snprintf(entry, sizeof entry, "%010zu 00000 n \n", o);
    out << entry;
  }
  out << "trailer\n<< /Size " << offset.size() + 1 << " /Root 1 0 R /Info 5 0 R >>\nstartxref\n" << xref
      << "\n%%EOF\n";
  os << out.str();
}

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_DEVELOPABILITY_PATTERN_CANVAS_H
