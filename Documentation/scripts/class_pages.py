"""Writes Documentation/classes/<Class>.md, one page per public Tyndall
class, from the Doxygen comments of Module/*/vtk*.h: the class comment, then
every documented public method or parameter group. Internal classes (their
comment says "Internal to Tyndall::...") are left out. Run from the repository
root after changing a header:

    python3 Documentation/scripts/class_pages.py
"""

import glob
import os
import re

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
OUT = os.path.join(ROOT, "Documentation", "classes")


def clean(comment):
    lines = []
    for line in comment.splitlines():
        line = re.sub(r"^\s*/?\*+/?", "", line).rstrip()
        if line.strip() in ("/", "///@{", "///@}"):
            continue
        lines.append(line[1:] if line.startswith(" ") else line)
    return "\n".join(lines).strip()


def page(header):
    text = open(header).read()
    name = os.path.splitext(os.path.basename(header))[0]
    folder = os.path.relpath(os.path.dirname(header), os.path.join(ROOT, "Module"))
    # Module/ParaView/Representation holds Tyndall::ParaViewRepresentation.
    module = folder.replace(os.sep, "")
    head = re.search(r"/\*\*(.*?)\*/", text, re.S)
    internal = head and re.search(r"[Ii]nternal to\s+Tyndall::", re.sub(r"\s*\*\s*", " ", head.group(1)))
    if not head or "@class" not in head.group(1) or internal:
        return None  # not a class, or an internal one (Documentation/architecture.md)
    body = clean(head.group(1))
    body = re.sub(r"@class\s+\S+\s*\n?", "", body)
    brief = re.search(r"@brief\s+(.*)", body)
    body = re.sub(r"@brief\s+.*\n?", "", body)
    body = body.replace("@sa", "See also:")
    out = ["# %s" % name, "",
           "*%s* — module `Tyndall::%s`, header `Module/%s/%s.h`." % (
               brief.group(1).strip() if brief else "", module, folder, name), "", body, "",
           "## Members", ""]
    public = text.split("public:", 1)[-1].split("protected:", 1)[0]
    for match in re.finditer(r"/\*\*(.*?)\*/\s*((?:[^;{]*?[;{]\s*){1,8}?)(?=\s*(?:///@}|/\*\*|$))",
                             public, re.S):
        doc = clean(match.group(1))
        decls = [d.strip() for d in re.findall(r"^\s*((?:static |virtual |void |bool |int |"
                                               r"double |const |VTK_WRAPEXCLUDE |vtk\w+)[^;{]*[;{]?)", match.group(2),
                                               re.M)]
        decls = [d.rstrip("{").strip() for d in decls if d and not d.startswith("//")]
        if not decls:
            continue
        out.append("```cpp")
        out.extend(decls)
        out.append("```")
        out.append("")
        out.append(doc)
        out.append("")
    return name, "\n".join(out) + "\n"


def main():
    os.makedirs(OUT, exist_ok=True)
    for old in glob.glob(os.path.join(OUT, "vtk*.md")):
        os.remove(old)
    index = ["# Tyndall's classes", "",
             "One page per public class, generated from the headers' Doxygen comments by "
             "`Documentation/scripts/class_pages.py`.", ""]
    headers = glob.glob(os.path.join(ROOT, "Module", "*", "vtk*.h")) + \
        glob.glob(os.path.join(ROOT, "Module", "ParaView", "*", "vtk*.h"))
    for header in sorted(headers):
        result = page(header)
        if not result:
            continue
        name, markdown = result
        with open(os.path.join(OUT, name + ".md"), "w") as f:
            f.write(markdown)
        brief = re.search(r"^\*(.*?)\* —", markdown.split("\n", 3)[2])
        index.append("- [%s](%s.md): %s" % (name, name, brief.group(1) if brief else ""))
    with open(os.path.join(OUT, "README.md"), "w") as f:
        f.write("\n".join(index) + "\n")
    print(OUT)


main()
