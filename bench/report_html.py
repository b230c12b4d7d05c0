"""report.md as a static HTML page (no server, no script): the Markdown subset report.py writes.

    from report_html import markdown_to_html
    html = markdown_to_html(markdown_text, title)

Handles what report.py produces and nothing more: `#`/`##` headings, pipe tables (an
alignment row after the header; `\\|` inside a cell), `- ` lists nested by two spaces,
paragraphs, and inline `code`, **bold**, images ![alt](src) and links [text](href), which may
hold an image. Everything else is text, escaped. Relative links stay relative, so the page
works from the report folder as it is (copied, zipped, opened from disk).
"""
import html
import re

STYLE = """body { font-family: sans-serif; margin: 1.5em; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.5em; vertical-align: middle; }
th { background: #f0f0f0; }
td.r { text-align: right; }
td img { width: 240px; height: auto; display: block; }
p img { max-width: 100%; }
code { background: #f4f4f4; padding: 0 0.2em; }"""


def inline(text):
    """Markdown inline markup of one line to HTML (the text escaped)."""
    parts = re.split(r"(`[^`]*`)", text)
    out = []
    for part in parts:
        if part.startswith("`") and part.endswith("`") and len(part) >= 2:
            out.append(f"<code>{html.escape(part[1:-1])}</code>")
            continue
        s = html.escape(part, quote=True)
        s = re.sub(r"\*\*(.+?)\*\*", r"<strong>\1</strong>", s)
        s = re.sub(r"!\[([^\]]*)\]\(([^)\s]+)\)", r'<img src="\2" alt="\1">', s)
        s = re.sub(r"\[([^\]]*)\]\(([^)\s]+)\)", r'<a href="\2">\1</a>', s)
        out.append(s)
    return "".join(out)


def cells(line):
    inner = line.strip()[1:-1] if line.strip().endswith("|") else line.strip()[1:]
    return [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", inner)]


def table(lines):
    head, align, body = cells(lines[0]), cells(lines[1]), [cells(l) for l in lines[2:]]
    right = [a.endswith(":") for a in align]
    out = ["<table>", "<tr>" + "".join(f"<th>{inline(c)}</th>" for c in head) + "</tr>"]
    for row in body:
        out.append("<tr>" + "".join(
            f'<td class="r">{inline(c)}</td>' if i < len(right) and right[i]
            else f"<td>{inline(c)}</td>" for i, c in enumerate(row)) + "</tr>")
    out.append("</table>")
    return out


def bullet_list(lines):
    out, depth = [], 0
    for line in lines:
        level = (len(line) - len(line.lstrip(" "))) // 2 + 1
        while depth < level:
            out.append("<ul>")
            depth += 1
        while depth > level:
            out.append("</ul>")
            depth -= 1
        out.append(f"<li>{inline(line.strip()[2:])}</li>")
    return out + ["</ul>"] * depth


def blocks(lines):
    """(kind, lines) runs: heading, table, list, paragraph."""
    i = 0
    while i < len(lines):
        line = lines[i]
        if not line.strip():
            i += 1
            continue
        if line.startswith("#"):
            yield "heading", [line]
            i += 1
            continue
        kind = ("table" if line.startswith("|") else
                "list" if line.lstrip(" ").startswith("- ") else "paragraph")
        j = i + 1
        while j < len(lines) and lines[j].strip() and not lines[j].startswith("#"):
            nxt = ("table" if lines[j].startswith("|") else
                   "list" if lines[j].lstrip(" ").startswith("- ") else "paragraph")
            if nxt != kind:
                break
            j += 1
        yield kind, lines[i:j]
        i = j


def markdown_to_html(markdown, title):
    body = []
    for kind, lines in blocks(markdown.splitlines()):
        if kind == "heading":
            level = min(len(lines[0]) - len(lines[0].lstrip("#")), 6)
            body.append(f"<h{level}>{inline(lines[0][level:].strip())}</h{level}>")
        elif kind == "table" and len(lines) >= 2:
            body += table(lines)
        elif kind == "list":
            body += bullet_list(lines)
        else:
            body.append("<p>" + " ".join(inline(l.strip()) for l in lines) + "</p>")
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            f"<title>{html.escape(title)}</title>\n<style>\n{STYLE}\n</style>\n</head>\n<body>\n"
            + "\n".join(body) + "\n</body>\n</html>\n")
