"""Where each language's rendered files go: `templates/<lang>/export.yaml`.

    root: verifiers/go                     # the language's folder, relative to the repository
    vectors: vectors                       # optional: the compact copy (one <family>.jsonl each,
                                           # and index.json), relative to root
    generated: [internal/names]            # optional: folders that hold only rendered files, so
                                           # anything else found there is reported as stale
    files:
      - {template: names.go.j2, output: internal/names/names.go}
      - {template: family.c.j2, output: "src/vectors/{family}.c", each: family}

A template sees `suite` (model.SuiteModel), `note` (the "generated, do not edit" sentence), the
filters of names.py and literals.py, and, with `each: family`, `family` (model.FamilyModel).
"""
from __future__ import annotations

import traceback
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import yaml

from plcvec.errors import PlcvecError
from plcvec.export import literals, names
from plcvec.export.model import SuiteModel, index_json

if TYPE_CHECKING:
    import jinja2

TEMPLATES = Path(__file__).resolve().parent / "templates"


def languages(templates: Path | None = None) -> list[str]:
    templates = templates or TEMPLATES
    return sorted(p.name for p in templates.iterdir() if (p / "export.yaml").is_file())


@dataclass
class Target:
    lang: str
    root: Path
    files: dict[str, str]          # path relative to the repository -> text
    generated_dirs: list[str]      # relative to the repository


def _read_config(folder: Path) -> dict:
    path = folder / "export.yaml"
    try:
        config = yaml.safe_load(path.read_text(encoding="utf-8"))
    except yaml.YAMLError as exc:
        raise PlcvecError(f"{path}: not valid YAML ({exc})")
    if not isinstance(config, dict) or not isinstance(config.get("root"), str):
        raise PlcvecError(f"{path}: needs `root` (the language's folder) and `files`")
    for i, entry in enumerate(config.get("files") or []):
        if not isinstance(entry, dict) or not {"template", "output"} <= set(entry) or \
                entry.get("each", "family") != "family":
            raise PlcvecError(f"{path}: files[{i}] needs `template` and `output` (and `each: family` or nothing)")
    return config


def _environment(folder: Path) -> jinja2.Environment:
    import jinja2

    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(folder)),
        undefined=jinja2.StrictUndefined,       # a misspelt name fails the export, not the compiler
        keep_trailing_newline=True, trim_blocks=True, lstrip_blocks=True, autoescape=False)
    env.filters.update(literals.FILTERS)
    env.filters.update(upper_snake=names.upper_snake, lower_snake=names.lower_snake,
                       pascal=names.pascal, camel=names.camel, digest=names.digest)
    return env


def _template_line(exc: jinja2.TemplateError, path: Path) -> str:
    """`file:line` of a template error: a syntax error carries it; an error while rendering is found
    in the traceback, where jinja2 puts the template's own file and line."""
    if getattr(exc, "lineno", None):
        return f"{getattr(exc, 'filename', None) or path}:{exc.lineno}"
    line = None
    for frame, lineno in traceback.walk_tb(exc.__traceback__):
        if frame.f_code.co_filename.endswith(".j2"):
            path, line = Path(frame.f_code.co_filename), lineno
    return f"{path}:{line}" if line else str(path)


def render(lang: str, model: SuiteModel, templates: Path | None = None) -> Target:
    # jinja2 is imported when a language is rendered, not with this module: `plcvec --help` and every
    # other command list the languages (languages()) without rendering any.
    import jinja2

    folder = (templates or TEMPLATES) / lang
    config = _read_config(folder)
    root = config["root"].rstrip("/")
    env = _environment(folder)
    files: dict[str, str] = {}
    for entry in config.get("files") or []:
        try:
            template = env.get_template(entry["template"])
            if entry.get("each") == "family":
                for fam in model.families:
                    out = entry["output"].format(family=fam.name.text)
                    files[f"{root}/{out}"] = template.render(suite=model, family=fam, note=model.generated_note)
            else:
                files[f"{root}/{entry['output']}"] = template.render(suite=model, note=model.generated_note)
        except jinja2.TemplateError as exc:
            raise PlcvecError(f"{_template_line(exc, folder / entry['template'])}: {exc}") from None
    generated = [f"{root}/{d.rstrip('/')}" for d in config.get("generated") or []]
    if config.get("vectors"):
        vec_dir = f"{root}/{config['vectors'].rstrip('/')}"
        for fam in model.families:
            files[f"{vec_dir}/{fam.name.text}.jsonl"] = fam.jsonl
        files[f"{vec_dir}/index.json"] = index_json(model)
        generated.append(vec_dir)
    return Target(lang, Path(root), files, generated)
