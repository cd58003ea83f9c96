#!/usr/bin/env python3
"""Texts that reach the window without the catalogue (docs/lecturers.md "German and English").

Every text a user reads goes through app/text/catalogue.h: ui::tr(s, "…"), text::Text("…"),
text::fill(lang, "…", …). A text written straight into a Dear ImGui call or one of the panels'
helpers (ui::checkbox, ui::section, …) would stay English in German: this finds each such string
literal in app/ui/, app/web/ and app/session/ (and the status line's setStatus) and fails naming file and line. A literal counts as a text when,
without its "##id" and its printf conversions, it has a word of two letters or more that is not one
of the lecture's symbols below (the same in both languages).

  untranslated_texts.py SOURCE_DIR     checks the tree
  untranslated_texts.py --self-test    checks that the check finds what it should
"""
import glob
import os
import re
import sys

# Dear ImGui's calls that show their string arguments, and the viewer's own helpers (app/ui/widgets.h).
IMGUI = ("Text|TextWrapped|TextUnformatted|TextDisabled|TextColored|BulletText|Button|SmallButton|Checkbox|"
         "RadioButton|MenuItem|BeginMenu|Begin|Selectable|CollapsingHeader|TreeNode|SliderFloat|SliderInt|"
         "DragFloat|DragInt|DragScalarN|InputText|InputDouble|InputFloat|Combo|SetTooltip|OpenPopup|"
         "BeginPopupModal|IsPopupOpen|LabelText|TableSetupColumn|BeginTabItem|ColorEdit3|ColorEdit4")
HELPERS = "checkbox|radio|section|sameLineIfFits|fitLabel|errorText|dragVec3|dragDouble|copyButton|setStatus"
CALL = re.compile(r"(?:ImGui::(?:%s)|\bui::(?:%s)|(?<![\w:.])(?:%s))\(" % (IMGUI, HELPERS, HELPERS))
LITERAL = re.compile(r'"((?:[^"\\\n]|\\.)*)"')
# A literal handed to the catalogue: ui::tr(s, "…"), Text("…"), text::fill(lang, "…"), key("…") (a Text).
THROUGH_CATALOGUE = re.compile(r'(\btr\(\s*[\w.]+,\s*|(?<!ImGui::)\bText\(\s*|\bfill\(\s*[\w.()]+,\s*|\bkey\(\s*)$')
# The lecture's symbols and formulas, the same in German and English.
SYMBOLS = {"VPD", "dmin", "dmax", "xmin", "xmax", "ymin", "ymax", "NPC", "WC", "DC", "MC", "VRC", "VRP", "PRP", "VUP",
           "Esc"}
# recordRect ids ("camera.vrp", "copy.npcFromVrc.text") and table column ids without a header row.
ID = re.compile(r"^[a-z][A-Za-z0-9_]*(\.[A-Za-z0-9_]+)+$")
COLUMN_IDS = {"what", "count"}


def arguments(src, start):
    """The text of a call's arguments from the character after its "(" to its ")"."""
    depth, i = 1, start
    while i < len(src) and depth:
        c = src[i]
        if c == '"':
            m = LITERAL.match(src, i)
            i = m.end() if m else i + 1
            continue
        depth += c == "("
        depth -= c == ")"
        i += 1
    return src[start:i - 1]


def is_text(literal):
    t = re.sub(r"##.*", "", literal)
    t = re.sub(r"%[-+ #0-9.]*[a-zA-Z]+", "", t)
    if ID.match(literal) or literal in COLUMN_IDS:
        return False
    return any(w not in SYMBOLS for w in re.findall(r"[A-Za-z]{2,}", t))


def untranslated(src):
    """(line, literal) of every text literal in a call that shows it, not through the catalogue."""
    found = []
    for call in CALL.finditer(src):
        args = arguments(src, call.end())
        previous_end = None
        for lit in LITERAL.finditer(args):
            # "…" "…": one literal in pieces, judged by its first piece's place
            joined = previous_end is not None and not args[previous_end:lit.start()].strip()
            previous_end = lit.end()
            if joined:
                continue
            where = call.end() + lit.start()
            if THROUGH_CATALOGUE.search(src[max(0, where - 60):where]):
                continue
            if is_text(lit.group(1)):
                found.append((src.count("\n", 0, call.start()) + 1, lit.group(1)))
    return found


def self_test():
    sample = '''
      ImGui::Text("Hello %d", n);                       // 2: a text
      ImGui::Button(ui::tr(s, "Save"));                 // through the catalogue
      ui::checkbox(tr(s_, "show the NPC cube"), &v);    // through the catalogue
      checkbox("grid", &v);                             // 5: a text
      ImGui::TextWrapped("VPD = %s   dmin = %s", a, b); // symbols
      ImGui::SliderFloat("##t", &t, 0.f, 4.f, "t = %.2f");
      ui::dragVec3(s, "VRP", "camera.vrp", c.vrp);
      ImGui::MenuItem(ui::tr(s_, "Quit"), key("Ctrl+Q"));
      ImGui::SetTooltip("%s: from %s to %s",            // 10: a text, the call over two lines
                        a, b, c);
      ImGui::Begin(fill(lang, "{1} view", {x}).c_str());
      ui::section(tr(s, "Vanishing points"));
      ImGui::TextWrapped("%s", tr(s, "one text in two pieces: "
                                     "the second piece is no text of its own"));
      ImGui::TextDisabled("one text "
                          "in two pieces");               // 16: a text
    '''
    got = untranslated(sample)
    want = [(2, "Hello %d"), (5, "grid"), (10, "%s: from %s to %s"), (16, "one text ")]
    if got != want:
        print("untranslated_texts.py --self-test: found %r, expected %r" % (got, want))
        return 1
    print("untranslated_texts.py --self-test: finds the %d texts of the sample and nothing else" % len(want))
    return 0


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        print("usage: untranslated_texts.py SOURCE_DIR | --self-test")
        return 2
    files = sorted(glob.glob(os.path.join(argv[1], "app/ui/*.cpp")) + glob.glob(os.path.join(argv[1], "app/web/*.cpp")) +
                   glob.glob(os.path.join(argv[1], "app/session/*.cpp")))
    if not files:
        print("untranslated_texts.py: no sources under %s" % argv[1])
        return 2
    problems = []
    for f in files:
        with open(f, encoding="utf-8") as text:
            for line, literal in untranslated(text.read()):
                problems.append('%s:%d: "%s" reaches the window without the catalogue (app/text/catalogue.h)'
                                % (os.path.relpath(f, argv[1]), line, literal))
    for p in problems:
        print(p)
    print("%d files checked, %d texts outside the catalogue" % (len(files), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
