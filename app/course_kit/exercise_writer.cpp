#include "course/assignment.h"
#include "app/course_kit/exercise_writer.h"

#include "course/exercise_answer.h"
#include "course/exercise_file.h"
#include "course/sheet_values.h"
#include "io/json_text.h"

#include "app/export/svg.h"
#include "app/render/headless.h"
#include "app/views/observer.h"
#include "base/error.h"
#include "course/rational.h"
#include "io/scene_io.h"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace vplab {

namespace {

// ---- A small document model, written out as Markdown or as LaTeX ------------------------------

struct Block {
  enum Kind { title, heading, paragraph, math, figure, items, numbered } kind;
  std::string text;                 // math: LaTeX; figure: the file's stem; others: text with $…$ math
  std::vector<std::string> list{};  // items, numbered
};
using Document = std::vector<Block>;

std::string markdown(const Document& doc) {
  std::string out;
  for (const Block& b : doc) {
    switch (b.kind) {
      case Block::title: out += "# " + b.text + "\n\n"; break;
      case Block::heading: out += "## " + b.text + "\n\n"; break;
      case Block::paragraph: out += b.text + "\n\n"; break;
      case Block::math: out += "$$\n" + b.text + "\n$$\n\n"; break;
      case Block::figure: out += "![" + b.list.at(0) + "](" + b.text + ".svg)\n\n"; break;
      case Block::items:
        for (const std::string& item : b.list) out += "- " + item + "\n";
        out += "\n";
        break;
      case Block::numbered:
        for (size_t i = 0; i < b.list.size(); ++i) out += std::to_string(i + 1) + ". " + b.list[i] + "\n";
        out += "\n";
        break;
    }
  }
  return out;
}

std::string latex(const Document& doc, Language lang) {
  // babel sets the hyphenation and the words LaTeX writes itself in the sheet's language; T1 with Latin
  // Modern hyphenates words with umlauts and needs no bitmap fonts made on the fly.
  std::string out =
      "\\documentclass[a4paper,11pt]{article}\n"
      "\\usepackage[utf8]{inputenc}\n"
      "\\usepackage[T1]{fontenc}\n"
      "\\usepackage{lmodern}\n"
      "\\usepackage[" + std::string(lang == Language::de ? "ngerman" : "english") + "]{babel}\n"
      "\\usepackage{amsmath,amssymb,graphicx}\n"
      "\\usepackage[margin=2cm]{geometry}\n"
      "\\setlength{\\parindent}{0pt}\\setlength{\\parskip}{0.6em}\n"
      // Lines of long formulas may end short rather than run into the margin.
      "\\setlength{\\emergencystretch}{3em}\n"
      "\\begin{document}\n";
  for (const Block& b : doc) {
    switch (b.kind) {
      case Block::title: out += "\\section*{" + b.text + "}\n\n"; break;
      case Block::heading: out += "\\subsection*{" + b.text + "}\n\n"; break;
      case Block::paragraph:
        // A list of formulas (inlineList) has few places to break: ragged, it never runs into the margin.
        if (b.text.find("$, $") != std::string::npos) out += "{\\raggedright " + b.text + "\\par}\n\n";
        else out += b.text + "\n\n";
        break;
      case Block::math: out += "\\[\n" + b.text + "\n\\]\n\n"; break;
      case Block::figure:
        // A minipage cannot be split: the figure and its caption stay on one page.
        out += "\\begin{center}\n\\begin{minipage}{0.7\\textwidth}\\centering\n\\includegraphics[width=\\linewidth]{" +
               b.text + ".png}\\\\[0.3em]\n" + b.list.at(0) + "\n\\end{minipage}\n\\end{center}\n\n";
        break;
      case Block::items:
        out += "\\begin{itemize}\n";
        for (const std::string& item : b.list) out += "\\item " + item + "\n";
        out += "\\end{itemize}\n\n";
        break;
      case Block::numbered:
        out += "\\begin{enumerate}\n";
        for (const std::string& item : b.list) out += "\\item " + item + "\n";
        out += "\\end{enumerate}\n\n";
        break;
    }
  }
  return out + "\\end{document}\n";
}

// ---- Numbers, vectors and matrices as LaTeX math -----------------------------------------------

std::string num(double x) { return latexNumber(x); }

std::string vec(std::initializer_list<double> xs) {
  std::string s = "(";
  for (double x : xs) s += (s.size() > 1 ? ",\\ " : "") + num(x);
  return s + ")";
}
std::string vec(const Vec3& v) { return vec({v.x, v.y, v.z}); }
std::string vec(const Vec4& v) { return vec({v.x, v.y, v.z, v.w}); }

double numberWidth(const std::string& latexNum);  // below, with the other widths

/// The printed width of a matrix's entries in characters (column by column, the widest entry).
double matrixWidth(const Mat4& m) {
  double w = 0;
  for (int c = 0; c < 4; ++c) {
    double widest = 0;
    for (const auto& r : rowsOf(m)) widest = std::max(widest, numberWidth(num(r[size_t(c)])));
    w += widest + 2;
  }
  return w;
}

std::string mat(const Mat4& m) {
  std::string s = "\\begin{pmatrix}";
  for (const auto& r : rowsOf(m)) {
    for (int c = 0; c < 4; ++c) s += (c ? " & " : " ") + num(r[size_t(c)]);
    s += " \\\\";
  }
  return s + " \\end{pmatrix}";
}

// ---- Keeping lines on the page -------------------------------------------------------------------
// TeX breaks a paragraph between formulas, never inside a displayed one nor at a comma inside an
// inline one: lists are written one formula per item, and displays whose estimated width would
// leave the text block are split.

/// The printed width of a LaTeX number in characters: a fraction is as wide as its longer part.
double numberWidth(const std::string& latexNum) {
  const size_t frac = latexNum.find("\\frac{");
  if (frac == std::string::npos) return double(latexNum.size());
  const size_t mid = latexNum.find("}{", frac), end = latexNum.rfind('}');
  const double a = double(mid - frac - 6), b = double(end - mid - 2);
  return double(frac) + std::max(a, b) * 0.8;  // the parts are set smaller
}

/// A rough width of a formula in characters: commands count as one, braces and scripts' markers as
/// none, a fraction as its wider part.
double mathWidth(std::string_view m) {
  double w = 0;
  for (size_t i = 0; i < m.size(); ++i) {
    const char ch = m[i];
    if (ch == '\\') {
      size_t j = i + 1;
      while (j < m.size() && std::isalpha(static_cast<unsigned char>(m[j]))) ++j;
      const std::string_view name = m.substr(i + 1, j - i - 1);
      if (name == "frac") {  // \frac{a}{b}
        const size_t mid = m.find("}{", j), end = mid == std::string_view::npos ? mid : m.find('}', mid + 2);
        if (end != std::string_view::npos) {
          w += std::max(mathWidth(m.substr(j + 1, mid - j - 1)), mathWidth(m.substr(mid + 2, end - mid - 2))) * 0.8;
          i = end;
          continue;
        }
      }
      w += name == "quad" ? 2 : name.empty() ? 0.5 : name.size() > 6 ? double(name.size()) * 0.7 : 1;  // \mathit{…}: its text counts
      i = name.empty() ? i + 1 : j - 1;
    } else if (ch != '{' && ch != '}' && ch != '^' && ch != '_' && ch != '&') {
      w += 1;
    }
  }
  return w;
}

/// What fits on one displayed line of an A4 page with 2 cm margins at 11 pt, in mathWidth's characters.
constexpr double kDisplayWidth = 62;

/// Formulas joined by \quad on display lines, a new line where the next would not fit.
std::vector<std::string> displayLines(const std::vector<std::string>& parts) {
  std::vector<std::string> lines;
  double width = 0;
  for (const std::string& part : parts) {
    const double w = mathWidth(part);
    if (!lines.empty() && width + 3 + w <= kDisplayWidth) {
      lines.back() += ",\\quad " + part;
      width += 3 + w;
    } else {
      lines.push_back(part);
      width = w;
    }
  }
  return lines;
}

/// Formulas in running text, one per item, so that a line may break between them.
std::string inlineList(const std::vector<std::string>& items, const std::string& separator = ", ") {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + "$" + items[i] + "$";
  return out;
}

// ---- The texts, in English and German ----------------------------------------------------------

struct Writer {
  const Exercise& e;
  const ExerciseSolution& s;
  Language lang;

  std::string L(const std::string& en, const std::string& de) const { return lang == Language::de ? de : en; }
  const Camera& cam() const { return e.scene.camera; }
  bool perspective() const { return cam().projection == Projection::perspective; }
  bool oblique() const { return cam().projection == Projection::oblique; }
  // Solutions number their sections from 1, whichever topic they show.
  mutable int sections_ = 0;
  std::string section() const { return std::to_string(++sections_) + ". "; }

  /// Formulas on as many displayed lines as the page's width needs.
  static void displays(Document& d, const std::vector<std::string>& parts) {
    for (std::string& line : displayLines(parts)) d.push_back({Block::math, std::move(line)});
  }

  bool shows(ExerciseTopic t) const { return exerciseShows(e.spec.topic, t); }

  std::string topicName() const {
    switch (e.spec.topic) {
      case ExerciseTopic::orientation: return L("View orientation", "View Orientation");
      case ExerciseTopic::mapping: return L("View mapping", "View Mapping");
      case ExerciseTopic::clipping: return L("Clipping in homogeneous coordinates", "Clipping in homogenen Koordinaten");
      case ExerciseTopic::pipeline: return L("The viewing pipeline", "Die Viewing-Pipeline");
    }
    return "";
  }
  std::string projectionName() const {
    switch (cam().projection) {
      case Projection::perspective: return L("perspective", "perspektivisch");
      case Projection::parallel: return L("parallel (orthographic)", "parallel (orthografisch)");
      case Projection::oblique: return L("oblique parallel", "schiefe Parallelprojektion");
    }
    return "";
  }

  // Two matrices: the column form p' = M·p (the dump's) and the lecture notes' row form p' = p·M^T.
  void matrixPair(Document& d, const std::string& name, const Mat4& m) const {
    const std::string column = name + " = " + mat(m), row = name + "^{T} = " + mat(glm::transpose(m));
    if (matrixWidth(m) * 2 + 16 <= kDisplayWidth) {
      d.push_back({Block::math, column + "\\qquad " + row});
    } else {  // side by side they would leave the page
      d.push_back({Block::math, column});
      d.push_back({Block::math, row});
    }
    d.push_back({Block::paragraph,
                 L("Left the column-vector form ($p' = M \\cdot p$, as answers give it); right the "
                   "lecture notes' row-vector form ($p' = p \\cdot M^T$), its transpose.",
                   "Links die Form für Spaltenvektoren ($p' = M \\cdot p$); rechts "
                   "die Form des Skripts für Zeilenvektoren ($p' = p \\cdot M^T$), ihre Transponierte.")});
  }

  std::string outcodeBits(Outcode c) const {
    std::string bits;
    for (int i = kPlaneCount - 1; i >= 0; --i) bits += (c >> i) & 1 ? '1' : '0';
    return bits;
  }

  std::string planeLabel(int plane) const {
    static const char* en[] = {"left", "right", "bottom", "top", "back", "front"};
    static const char* de[] = {"links", "rechts", "unten", "oben", "hinten", "vorne"};
    return lang == Language::de ? de[plane] : en[plane];
  }
  static std::string bcFormula(int plane) {
    static const char* f[] = {"x", "w - x", "y", "w - y", "z", "w - z"};
    return f[plane];
  }

  void givenBlocks(Document& d) const {
    const Camera& c = cam();
    d.push_back({Block::heading, L("Given", "Gegeben")});
    std::vector<std::string> items = {
        "VRP $= " + vec(c.vrp) + "$, " + L("PRP", "Projektionszentrum PRP") + " $= " + vec(c.prp) + "$, VUP $= " + vec(c.vup) + "$ " + L("(WC)", "(WC)"),
        L("window", "Fenster (Window)") + " $x_{min} = " + num(c.window.xmin) + ",\\ x_{max} = " + num(c.window.xmax) +
            ",\\ y_{min} = " + num(c.window.ymin) + ",\\ y_{max} = " + num(c.window.ymax) + "$ " +
            L("in the view plane (VRC)", "in der Sichtebene (Bildebene, VRC)"),
        L("front plane", "vordere Clippingebene (Front Plane)") + " $F = " + num(c.front) + "$, " + L("back plane", "hintere Clippingebene (Back Plane)") +
            " $B = " + num(c.back) + "$ (VRC z)",
        L("projection: ", "Projektion: ") + projectionName() +
            (oblique() ? ", $d = " + num(c.oblique.d) + ",\\ \\varphi = " + num(c.oblique.phiDeg) + "^\\circ$" : ""),
        L("device", "Ausgabegerät") + " $W \\times H = " + std::to_string(e.scene.device.width) + " \\times " +
            std::to_string(e.scene.device.height) + "$ " + L("pixels, origin top left, y down", "Pixel, Ursprung oben links, y nach unten"),
    };
    const SceneObject& o = e.scene.objects[0];
    std::vector<std::string> poly;
    for (size_t i = 0; i < o.vertices.size(); ++i)
      poly.push_back("P_" + std::to_string(i + 1) + " = " + vec(o.vertices[i]));
    items.push_back(L("the polygon ", "das Polygon ") + inlineList(poly) + " " + L("in MC", "in Modellkoordinaten (MC)"));
    std::string model = "\\mathit{wcFromMc} = ";
    model += "T" + vec(o.transform.translate);
    for (auto it = o.transform.rotations.rbegin(); it != o.transform.rotations.rend(); ++it)
      model += " \\cdot R_{" + vec(it->axis) + "}(" + num(it->deg) + "^\\circ)";
    model += " \\cdot S(" + num(o.transform.scale.x) + ")";
    items.push_back(L("placed in WC by ", "in WC gesetzt durch ") + "$" + model + "$");
    d.push_back({Block::items, "", items});
    if (e.spec.topic == ExerciseTopic::mapping)
      d.push_back({Block::paragraph, L("For the view mapping, $P_1$ in VRC is ", "Für das View Mapping ist $P_1$ in VRC ") +
                                         "$" + vec(s.point.vrc) + "$."});
    if (e.spec.topic == ExerciseTopic::clipping) {
      std::vector<std::string> pts;
      for (size_t i = 0; i < s.vertices.size(); ++i)
        pts.push_back("P_" + std::to_string(i + 1) + " = " + vec(s.vertices[i].npcH));
      d.push_back({Block::paragraph, L("The polygon in homogeneous NPC $(x, y, z, w)$ is ",
                                       "Das Polygon in homogenen NPC $(x, y, z, w)$ ist ") + inlineList(pts) + "."});
    }
  }

  // The tasks as the grader counts them (course/exercise_answer.h): numbered, each with its points.
  std::string pointsText(double p) const {
    char text[32];
    std::snprintf(text, sizeof text, "%g", p);
    return text + (p == 1 ? L(" point", " Punkt") : L(" points", " Punkte"));
  }
  std::vector<std::string> tasks() const {
    std::vector<std::string> t;
    for (const ExerciseTask& task : exerciseTasks(e, s, lang)) t.push_back(task.text + " (" + pointsText(points(task)) + ")");
    return t;
  }
  double totalPoints() const {
    double sum = 0;
    for (const ExerciseTask& task : exerciseTasks(e, s, lang)) sum += points(task);
    return sum;
  }

  Document sheet() const {
    Document d;
    d.push_back({Block::title, L("Exercise", "Übung") + " " + std::to_string(e.spec.seed) + ": " + topicName()});
    if (!e.studentId.empty())
      d.push_back({Block::paragraph, L("Your own variant, for ", "Ihre eigene Variante, für ") + e.studentId + "."});
    givenBlocks(d);
    d.push_back({Block::figure, "world", {L("The scene, the camera and its view volume (world view).",
                                            "Szene, Kamera und Sichtvolumen (Weltansicht).")}});
    d.push_back({Block::heading, L("Tasks", "Aufgaben")});
    d.push_back({Block::numbered, "", tasks()});
    d.push_back({Block::paragraph, L("In all: ", "Insgesamt: ") + pointsText(totalPoints()) + "."});
    d.push_back({Block::paragraph, L("Conventions (as in the lecture notes): column vectors; $N = (PRP - VRP)/|PRP - VRP|$; "
                                     "front $\\to z = 1$, back $\\to z = 0$; inside when $0 \\le x, y, z \\le w$.",
                                     "Konventionen: Spaltenvektoren; $N = (PRP - VRP)/|PRP - VRP|$; "
                                     "vorne $\\to z = 1$, hinten $\\to z = 0$; innen, wenn $0 \\le x, y, z \\le w$.")});
    d.push_back({Block::paragraph, answeringText()});
    return d;
  }

  // The precision the grader expects and how to hand in (issue 38): rounding within it costs nothing.
  std::string answeringText() const {
    const double tolerance = Assignment{}.tolerance;  // what exerciseAssignment writes
    const int decimals = int(std::ceil(std::log10(0.5 / tolerance) - 1e-9));
    const std::string n = std::to_string(decimals);
    return L("Answering: give each number exactly (a fraction such as -3/5) or with at least " + n +
                 " decimals (a decimal comma is fine); rounding to " + n + " decimals costs nothing. Write the "
                 "matrices for column vectors ($p' = M \\cdot p$), or every one of them for row vectors as in the lecture "
                 "notes ($p' = p \\cdot M$). Hand in answer.json with your numbers in place of null; an item left null is "
                 "not answered.",
             "Abgabe: Geben Sie jede Zahl exakt (als Bruch wie -3/5) oder mit mindestens " + n +
                 " Nachkommastellen an (ein Dezimalkomma ist erlaubt); Runden auf " + n + " Nachkommastellen kostet "
                 "nichts. Schreiben Sie die Matrizen für Spaltenvektoren ($p' = M \\cdot p$) oder alle für Zeilenvektoren "
                 "wie im Skript ($p' = p \\cdot M$). Geben Sie answer.json mit Ihren Zahlen anstelle von null ab; ein "
                 "Eintrag, der null bleibt, gilt als nicht beantwortet.");
  }

  void modeling(Document& d) const {
    d.push_back({Block::heading, section() + L("Modeling (lecture notes 15.2.1): MC to WC", "Modeling (Skript 15.2.1): MC nach WC")});
    d.push_back({Block::paragraph, L("Scale first, then rotate, then translate: ", "Erst skalieren, dann drehen, dann verschieben: ") +
                                       "$\\mathit{wcFromMc} = T \\cdot R \\cdot S$."});
    matrixPair(d, "\\mathit{wcFromMc}", s.wcFromMc);
    d.push_back({Block::math, "P_1^{WC} = \\mathit{wcFromMc} \\cdot " + vec(s.point.mc) + " = " + vec(s.point.wc)});
  }

  void orientation(Document& d) const {
    const VrcAxes& f = s.run.vrc;
    const Camera& c = cam();
    d.push_back({Block::heading, section() + L("View orientation (15.2.2): WC to VRC", "View Orientation (15.2.2): WC nach VRC")});
    const Vec3 cross = glm::cross(c.vup, f.n);
    displays(d, {"PRP - VRP = " + vec(c.prp - c.vrp), "VPD = |PRP - VRP| = " + num(f.vpd),
                 "N = \\frac{PRP - VRP}{VPD} = " + vec(f.n)});
    displays(d, {"VUP \\times N = " + vec(cross), "U = \\frac{VUP \\times N}{|VUP \\times N|} = " + vec(f.u),
                 "V = N \\times U = " + vec(f.v)});
    d.push_back({Block::paragraph, L("$U$, $V$, $N$ as rows, after the translation by $-VRP$: ",
                                     "$U$, $V$, $N$ als Zeilen, nach der Verschiebung um $-VRP$: ") +
                                       "$\\mathit{vrcFromWc} = [U\\ 0;\\ V\\ 0;\\ N\\ 0;\\ 0\\ 0\\ 0\\ 1] \\cdot T(-VRP)$."});
    matrixPair(d, "\\mathit{vrcFromWc}", s.run.vrcFromWc);
    d.push_back({Block::math, "P_1^{VRC} = \\mathit{vrcFromWc} \\cdot P_1^{WC} = " + vec(s.point.vrc)});
  }

  void mapping(Document& d) const {
    const VrcAxes& f = s.run.vrc;
    const Camera& c = cam();
    const Mat4& m = s.run.npcFromVrc;
    d.push_back({Block::heading, section() + L("View mapping (14, 15.2.3–15.2.4): VRC to homogeneous NPC",
                                   "View Mapping (14, 15.2.3–15.2.4): VRC nach homogenen NPC")});
    if (perspective()) {
      displays(d, {"d = VPD = " + num(f.vpd), "d_{min} = VPD - F = " + num(f.dmin), "d_{max} = VPD - B = " + num(f.dmax),
                   "k = \\frac{d_{min}}{d_{max} - d_{min}} = " + num(m[2][2])});
      d.push_back({Block::paragraph,
                   L("The shear into a regular pyramid and the scaling into the cube, folded into one matrix; "
                     "$w' = z_e = VPD - z$ is the distance in front of the eye.",
                     "Scherung in eine reguläre Pyramide und Skalierung in den Würfel, in einer Matrix; "
                     "$w' = z_e = VPD - z$ ist der Abstand vor dem Auge.")});
    } else {
      if (oblique()) {
        const double dc = c.oblique.d * std::cos(radians(c.oblique.phiDeg));
        const double ds = c.oblique.d * std::sin(radians(c.oblique.phiDeg));
        displays(d, {"x_s = x + z \\cdot d\\cos\\varphi = x + " + num(dc) + "\\,z",
                     "y_s = y - z \\cdot d\\sin\\varphi = y - " + num(ds) + "\\,z"});
      }
      displays(d, {"x' = \\frac{x_s - x_{min}}{x_{max} - x_{min}}", "y' = \\frac{y_s - y_{min}}{y_{max} - y_{min}}",
                   "z' = \\frac{z - B}{F - B}", "w' = 1"});
    }
    matrixPair(d, "\\mathit{npcFromVrc}", m);
    d.push_back({Block::math, "P_1^{NPC_h} = \\mathit{npcFromVrc} \\cdot P_1^{VRC} = " + vec(s.point.npcH)});
  }

  void pointClipAndDevice(Document& d) const {
    const PointStages& p = s.point;
    d.push_back({Block::heading, section() + L("Clipping test of $P_1$ (15.2.4, Hill 7.4)", "Clipping-Test von $P_1$ (15.2.4, Hill 7.4)")});
    std::vector<std::string> bc;
    for (int i = 0; i < kPlaneCount; ++i) bc.push_back("BC_" + std::to_string(i) + " = " + num(p.bc[size_t(i)]));
    displays(d, bc);
    d.push_back({Block::paragraph, L("Outcode (bits 5 … 0: front, back, top, bottom, right, left; a bit is set when its "
                                     "boundary coordinate is negative): ",
                                     "Outcode (Bits 5 … 0: vorne, hinten, oben, unten, rechts, links; gesetzt, wenn die "
                                     "Randkoordinate negativ ist): ") +
                                       "$" + outcodeBits(p.outcode) + "_2 = " + std::to_string(p.outcode) + "$."});
    d.push_back({Block::heading, section() + L("Division by w and device mapping (15.2.5)", "Division durch w und Device Mapping (15.2.5)")});
    d.push_back({Block::paragraph, L("$x_{DC} = W \\cdot x,\\ y_{DC} = H \\cdot (1 - y),\\ z_{DC} = z$: origin top left, y down.",
                                     "$x_{DC} = W \\cdot x,\\ y_{DC} = H \\cdot (1 - y),\\ z_{DC} = z$: Ursprung oben links, y nach unten.")});
    matrixPair(d, "\\mathit{dcFromNpc}", s.run.dcFromNpc);
    if (p.outcode == 0) {
      d.push_back({Block::math, "P_1^{NPC} = \\left(\\frac{x}{w},\\ \\frac{y}{w},\\ \\frac{z}{w}\\right) = " + vec(p.npc)});
      d.push_back({Block::math, "P_1^{DC} = \\mathit{dcFromNpc} \\cdot P_1^{NPC} = " + vec(p.dc)});
    } else if (p.npcH.w < 0) {
      d.push_back({Block::paragraph,
                   L("$w = " + num(p.npcH.w) + " < 0$: $P_1$ lies behind the eye. It is clipped away before the "
                     "division. Dividing first would give $" + vec(p.npc) + "$: $x/w$ and $y/w$ flip sign, and the "
                     "point could land inside the cube (the divide-first mistake, Hill 7.4).",
                     "$w = " + num(p.npcH.w) + " < 0$: $P_1$ liegt hinter dem Auge und wird vor der Division "
                     "weggeclippt. Zuerst zu dividieren ergäbe $" + vec(p.npc) + "$: $x/w$ und $y/w$ wechseln das "
                     "Vorzeichen, der Punkt könnte im Würfel landen (der Fehler, vor dem Clipping zu dividieren, Hill 7.4).")});
    } else {
      d.push_back({Block::paragraph, L("$P_1$ lies outside the view volume: it is not mapped to DC.",
                                       "$P_1$ liegt außerhalb des Sichtvolumens und wird nicht auf DC abgebildet.")});
    }
  }

  void polygonClipping(Document& d) const {
    d.push_back({Block::heading, section() + L("Clipping the polygon (Sutherland–Hodgman in homogeneous coordinates)",
                                   "Clipping des Polygons (Sutherland–Hodgman in homogenen Koordinaten)")});
    std::vector<std::string> verts;
    Outcode all = 0xff, any = 0;
    for (size_t i = 0; i < s.vertices.size(); ++i) {
      const PointStages& v = s.vertices[i];
      all &= v.outcode, any |= v.outcode;
      verts.push_back("$P_" + std::to_string(i + 1) + " = " + vec(v.npcH) + "$, outcode $" + outcodeBits(v.outcode) + "_2$");
    }
    d.push_back({Block::items, "", verts});
    d.push_back({Block::paragraph, L("AND of the outcodes ", "UND der Outcodes ") + "$= " + outcodeBits(all) + "_2$, " +
                                       L("OR ", "ODER ") + "$= " + outcodeBits(any) + "_2$: " +
                                       L("neither trivially rejected nor accepted; clip against the planes whose bits are set. "
                                         "Intersection at $t = BC(P_{in}) / (BC(P_{in}) - BC(P_{out}))$ from the inside vertex.",
                                         "weder trivial verworfen noch akzeptiert; geclippt wird an den Ebenen der gesetzten Bits. "
                                         "Schnittpunkt bei $t = BC(P_{in}) / (BC(P_{in}) - BC(P_{out}))$ vom inneren Punkt aus.")});
    for (size_t k = 0; k < s.steps.size() && k < size_t(kPlaneCount); ++k) {
      const ClipStep& step = s.steps[k];
      const int plane = step.plane;
      std::string head = L("Plane ", "Ebene ") + planeLabel(plane) + " ($BC_" + std::to_string(plane) + " = " +
                         bcFormula(plane) + " \\ge 0$)";
      if (step.skipped) {
        d.push_back({Block::paragraph, "**" + head + "**: " + L("no vertex outside, nothing to do.", "kein Punkt außerhalb, nichts zu tun.")});
        continue;
      }
      std::vector<std::string> bcs;
      for (size_t i = 0; i < step.boundary.size(); ++i)
        bcs.push_back("Q_" + std::to_string(i + 1) + ": " + num(step.boundary[i]));
      d.push_back({Block::paragraph, "**" + head + "**: " + L("input ", "Eingabe ") + "$Q_1 \\ldots Q_" +
                                         std::to_string(step.input.size()) + "$, " + L("boundary values ", "Randwerte ") + inlineList(bcs) + "."});
      std::vector<std::string> cuts;
      for (const ClipIntersection& c : s.intersections[k])
        cuts.push_back(L("edge ", "Kante ") + "$Q_" + std::to_string(c.inside + 1) + " Q_" + std::to_string(c.outside + 1) +
                       "$: $t = " + num(c.t) + "$, " + L("new vertex ", "neuer Punkt ") + "$" + vec(c.vertex) + "$");
      d.push_back({Block::items, "", cuts});
      std::vector<std::string> out;
      for (const ClipVertex& v : step.output) out.push_back(vec(v.p));
      d.push_back({Block::paragraph, L("Result: ", "Ergebnis: ") + (out.empty() ? L("nothing remains.", "nichts bleibt.") : inlineList(out))});
    }
    d.push_back({Block::paragraph, L("Divided by $w$ and mapped to DC, the clipped polygon is",
                                     "Durch $w$ dividiert und auf DC abgebildet ist das geclippte Polygon")});
    std::vector<std::string> dcs;
    for (size_t i = 0; i < s.clippedDc.size(); ++i)
      dcs.push_back("$" + vec(divideByW(s.clippedNpcH[i])) + " \\to " + vec(s.clippedDc[i]) + "$");
    d.push_back({Block::items, "", dcs});
  }

  Document solution() const {
    Document d;
    sections_ = 0;
    d.push_back({Block::title, L("Solution", "Lösung") + " " + std::to_string(e.spec.seed) + ": " + topicName()});
    if (!e.studentId.empty())
      d.push_back({Block::paragraph, L("The variant for ", "Die Variante für ") + e.studentId + "."});
    d.push_back({Block::paragraph, L("Exact fractions where the values are small rationals, else decimals rounded to 4 places.",
                                     "Exakte Brüche, wo die Werte kleine rationale Zahlen sind, sonst auf 4 Stellen gerundete Dezimalzahlen.")});
    if (shows(ExerciseTopic::orientation)) {
      modeling(d);
      orientation(d);
    }
    if (shows(ExerciseTopic::mapping)) {
      mapping(d);
      pointClipAndDevice(d);
    }
    if (shows(ExerciseTopic::clipping)) polygonClipping(d);
    // Each topic carries only its own figures: the NPC view shows the mapping and the clipping.
    if (shows(ExerciseTopic::mapping) || shows(ExerciseTopic::clipping))
      d.push_back({Block::figure, "npc", {L("After view mapping, clipping and the division by w (NPC view).",
                                            "Nach View Mapping, Clipping und Division durch w (NPC-Ansicht).")}});
    return d;
  }
};

// Markdown bold (**…**) has no LaTeX meaning: there it becomes \textbf.
std::string boldToLatex(std::string s) {
  for (size_t at; (at = s.find("**")) != std::string::npos;) {
    const size_t end = s.find("**", at + 2);
    if (end == std::string::npos) break;
    s = s.substr(0, at) + "\\textbf{" + s.substr(at + 2, end - at - 2) + "}" + s.substr(end + 2);
  }
  return s;
}

void writeText(const std::string& text, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw Error(file.string() + ": cannot write");
}

}  // namespace

ExerciseDocuments exerciseDocuments(const Exercise& exercise, const ExerciseSolution& solution, Language lang) {
  const Writer w{exercise, solution, lang};
  const Document sheet = w.sheet(), sol = w.solution();
  return {markdown(sheet), markdown(sol), boldToLatex(latex(sheet, lang)), boldToLatex(latex(sol, lang))};
}

RenderRequest exerciseFigureRequest(const Exercise& exercise, ViewKind view, Language lang) {
  // Vector lines (hidden-line style, made on the CPU), printed: the light theme (white ground, the
  // view volume thin and solid, the window thick and dashed, the polygon thick with its vertices named
  // P1 … Pn), labels in the sheet's language and large enough to read at the figure's printed width.
  RenderRequest request;
  request.view = view;
  request.style = Style::hiddenLine;
  request.width = 800;
  request.height = 600;
  request.scale = kExerciseFigureScale;
  DisplaySettings display = displaySettingsFor(exercise.scene, request.style, 4.0 / 3.0);
  display.world.orbit = viewVolumeOrbit(exercise.scene, 4.0 / 3.0);
  display.theme = Theme::light;
  display.language = lang;
  display.overlays.vertexNames = true;
  request.display = display;
  return request;
}

void writeExercise(const Exercise& exercise, Language lang, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(dir.string() + ": cannot create the folder: " + ec.message());
  const ExerciseSolution solution = solveExercise(exercise);
  const ExerciseDocuments docs = exerciseDocuments(exercise, solution, lang);
  writeText(docs.sheetMd, dir / "sheet.md");
  writeText(docs.solutionMd, dir / "solution.md");
  writeText(docs.sheetTex, dir / "sheet.tex");
  writeText(docs.solutionTex, dir / "solution.tex");
  writeText(sceneToJson(exercise.scene), dir / "scene.json");
  // Which exercise this is, for the viewer (`vplab --exercise DIR`, issue 40).
  const ExerciseRef ref{exercise.spec, exercise.studentId, lang};
  writeText(exerciseFileJson(ref), dir / "exercise.json");
  // What the sheet asks for: the grader's assignment and the template a student fills in.
  const Assignment assignment = exerciseAssignment(exercise, solution, lang);
  writeText(assignmentJson(assignment), dir / "assignment.json");
  const nlohmann::ordered_json reference = referenceAnswer(exercise.scene);
  writeText(prettyJson(answerNamingExercise(answerTemplate(assignment, reference), ref)) + "\n", dir / "answer.json");
  writeText(prettyJson(answerKey(assignment, reference)) + "\n", dir / "solution.json");
  // The figures: the world view for the sheet, the NPC view for the solution, as SVG and as the
  // same drawing in PNG for LaTeX.
  auto context = createHeadlessContext(Backend::automatic, false);
  ViewRenderer renderer(*context, kExerciseFigureScale);
  for (const auto& [view, name] : {std::pair{ViewKind::world, "world"}, std::pair{ViewKind::npc, "npc"}}) {
    if (view == ViewKind::npc && exercise.spec.topic == ExerciseTopic::orientation) continue;  // not in its solution
    const RenderRequest request = exerciseFigureRequest(exercise, view, lang);
    writeSvg(svgOfRequest(exercise.scene, request), dir / (std::string(name) + ".svg"));
    writePng(renderImage(renderer, exercise.scene, request), dir / (std::string(name) + ".png"));
  }
}

}  // namespace vplab
