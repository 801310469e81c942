"""Every ```python block of docs/python.md runs, in order, in one namespace."""

import re


def test_docs_python_md_examples_run(repo, capsys):
    text = (repo / "docs/python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 4
    namespace: dict = {}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/python.md block {i + 1}", "exec"), namespace)
