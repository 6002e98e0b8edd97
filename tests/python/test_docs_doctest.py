"""Every Python example of docs/python.md runs: each fenced ```python block is a doctest (`>>>`
lines and their expected output), run with the doctest module; a python block without `>>>`
fails (it would not be checked)."""
import doctest
import pathlib
import re

import pytest

from conftest import SOURCE_DIR

DOC = pathlib.Path(SOURCE_DIR) / "docs" / "python.md"
BLOCKS = re.findall(r"^```python\n(.*?)^```", DOC.read_text(), re.S | re.M)


def test_the_page_has_examples_and_every_python_block_is_a_doctest():
    assert BLOCKS
    for block in BLOCKS:
        assert block.lstrip().startswith(">>>"), block[:80]


@pytest.mark.parametrize("k", range(len(BLOCKS)))
def test_the_block_runs_as_a_doctest(k):
    test = doctest.DocTestParser().get_doctest(BLOCKS[k], {}, f"docs/python.md block {k + 1}", str(DOC), 0)
    assert test.examples
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0 and result.attempted == len(test.examples)
