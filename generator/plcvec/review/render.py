"""Fill the review templates: one self-contained HTML file and the same content as Markdown.

HTML is autoescaped (spec text is data, never markup) and undefined names fail loudly, so a template
that asks for something the model does not hold is a bug found at once, not a blank cell.
"""
import re
from pathlib import Path

import jinja2

TEMPLATES = Path(__file__).resolve().parent / "templates"


def md_cell(text):
    """Text safe inside a Markdown table cell: pipes escaped, one line, and nothing a renderer takes as an HTML tag.

    Only a `<` that could open a tag is escaped, so the manual's `<>`, `<=` and `(s1) < (s2)` stay readable in a diff.
    """
    text = re.sub(r"\s*\n\s*", " ", str(text)).replace("\\", "\\\\").replace("|", "\\|")
    return re.sub(r"<(?=[A-Za-z/!?])", "&lt;", text)


def md_code(text):
    """A Markdown code span: its content is shown as it is (no tags, no entities), so only pipes need escaping."""
    text = re.sub(r"\s*\n\s*", " ", str(text)).replace("|", "\\|")
    fence = "``" if "`" in text else "`"
    return f"{fence}{text}{fence}" if fence == "`" else f"{fence} {text} {fence}"


def environment():
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(TEMPLATES)),
        autoescape=jinja2.select_autoescape(enabled_extensions=("html.j2",), disabled_extensions=("md.j2",),
                                            default=True),
        undefined=jinja2.StrictUndefined,
        trim_blocks=True, lstrip_blocks=True, keep_trailing_newline=True)
    env.filters["md"] = md_cell
    env.filters["code"] = md_code
    return env


def render(model):
    """{"review.html": text, "review.md": text} for the model of plcvec.review.model.build_model."""
    env = environment()
    return {"review.html": env.get_template("review.html.j2").render(m=model),
            "review.md": env.get_template("review.md.j2").render(m=model)}
