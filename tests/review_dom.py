"""A small DOM for the review tests: the HTML as a tree, elements by id, text as a reader sees it.

Built on the standard library's html.parser so the tests need nothing else; it reads both the file
`plcvec review` writes and the DOM Chromium serializes with --dump-dom.
"""
import re
from html.parser import HTMLParser

VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "track", "wbr"}


class Node:
    def __init__(self, tag, attrs, parent=None):
        self.tag, self.attrs, self.parent, self.children = tag, dict(attrs), parent, []

    def text(self):
        """The text content, white space collapsed as a browser shows it."""
        parts = []

        def walk(node):
            for child in node.children:
                if isinstance(child, str):
                    parts.append(child)
                else:
                    if child.tag == "br":
                        parts.append(" ")
                    walk(child)
        walk(self)
        return re.sub(r"\s+", " ", "".join(parts)).strip()

    def find_all(self, tag=None, cls=None):
        found = []
        for child in self.children:
            if isinstance(child, Node):
                if (tag is None or child.tag == tag) and (cls is None or cls in child.attrs.get("class", "").split()):
                    found.append(child)
                found += child.find_all(tag, cls)
        return found

    def first(self, tag=None, cls=None):
        found = self.find_all(tag, cls)
        assert found, f"no <{tag} class={cls}> in <{self.tag} id={self.attrs.get('id')}>"
        return found[0]


class _Builder(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.root = Node("#document", {})
        self.current = self.root
        self.ids = {}

    def handle_starttag(self, tag, attrs):
        node = Node(tag, attrs, self.current)
        self.current.children.append(node)
        if "id" in node.attrs:
            assert node.attrs["id"] not in self.ids, f"duplicate id {node.attrs['id']}"
            self.ids[node.attrs["id"]] = node
        if tag not in VOID:
            self.current = node

    def handle_startendtag(self, tag, attrs):
        self.handle_starttag(tag, attrs)
        if tag not in VOID:
            self.current = self.current.parent

    def handle_endtag(self, tag):
        node = self.current
        while node is not self.root and node.tag != tag:  # close elements left open (e.g. <p>)
            node = node.parent
        if node is not self.root:
            self.current = node.parent

    def handle_data(self, data):
        self.current.children.append(data)


def parse(html):
    """(root node, {id: node})."""
    builder = _Builder()
    builder.feed(html)
    builder.close()
    return builder.root, builder.ids


def disagreeing_cells(ids, family, example):
    """{printed cell: (printed, derived)} of the audit's cell-disagrees rows for one example's table."""
    prefix = f"audit-{family}-{example}-cell-disagrees"
    return {node.first("td", "cell").text(): (node.first("td", "printed").text(), node.first("td", "derived").text())
            for anchor, node in ids.items() if anchor.startswith(prefix)}
