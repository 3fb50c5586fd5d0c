"""The one way the figure scripts write into docs/: replace what stands
between <!-- NAME:begin --> and <!-- NAME:end --> in a page, markers kept.

    from doc_markers import put
    put('docs/bench.md', 'bench-table', ['| a | b |', ...])
"""


def put(doc, name, lines):
    text = open(doc).read()
    b, e = '<!-- %s:begin -->' % name, '<!-- %s:end -->' % name
    i, j = text.index(b), text.index(e) + len(e)
    open(doc, 'w').write(text[:i] + '\n'.join([b] + lines + [e]) + text[j:])
