#!/usr/bin/python3
"""Rewrites the docs' generated blocks from the committed CSVs: the text
between a page's `<!-- BEGIN GENERATED: NAME -->` and `<!-- END GENERATED:
NAME -->` markers, as lab/check_docs.py's GENERATORS write it (today: the
engines' translation notes at the end of doc/peers.md, from
doc/results/peers-notes.csv). The text outside the markers is left as it is;
lab/check_docs.py fails while a block differs from what its generator writes.

Usage: write_doc_blocks.py [--check] [REPO_ROOT]
(exit 0: every block written, or with --check already current; 1: with
--check, a block that is not; 2: bad usage)"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import check_docs  # noqa: E402  (the blocks' markers and generators)
from odelab_report import files  # noqa: E402  (the one writer)


def rewritten(root, text):
    """`text` with each generated block replaced by what its generator
    writes; a block no generator writes is left for check_docs to report."""
    def block(match):
        generator = next((g for prefix, g in check_docs.GENERATORS.items() if match.group(1).startswith(prefix)),
                         None)
        if generator is None:
            return match.group(0)
        end = match.group(0)[match.group(0).rindex("<!-- END GENERATED:"):]
        return f"<!-- BEGIN GENERATED: {match.group(1)} -->\n{generator(root).strip(chr(10))}\n{end}"
    return check_docs.BLOCK.sub(block, text)


def main(argv):
    check = "--check" in argv
    rest = [a for a in argv if a != "--check"]
    if len(rest) > 1 or any(a.startswith("-") for a in rest):
        sys.stderr.write(__doc__)
        return 2
    root = Path(rest[0] if rest else Path(__file__).resolve().parents[1])
    if not (root / "doc").is_dir():
        sys.stderr.write(f"write_doc_blocks: {root} is not the project's root (no doc/ folder)\n")
        return 2
    stale = []
    for page in check_docs.pages(root):
        if not page.exists():
            continue
        text = page.read_text()
        new = rewritten(root, text)
        if new != text:
            stale.append(page)
            if not check:
                files.write_atomically(page, new)
                print(f"write_doc_blocks: {page.relative_to(root)}: generated blocks rewritten")
    if check:
        for page in stale:
            print(f"write_doc_blocks: {page.relative_to(root)}: a generated block is not current")
        return 1 if stale else 0
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
