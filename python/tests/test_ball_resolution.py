"""A preset ball is resolved in one place (issue 55 item 1): python/src/arguments/ball.rs over the
catalog's cache (catalog_cache.rs, preset_balls.rs), as the command line resolves its
`BallArgs`. A binding that loaded the catalog and built a `Ball` of its own (collide's
`target_preset` did) could drift from the others' names, defaults and errors."""

import re
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"
# where the catalog is read and a preset's Ball built
RESOLVERS = {"arguments/ball.rs", "catalog_cache.rs", "preset_balls.rs"}
BUILDS = re.compile(r"\bBall::from_entry(_with)?\(|\bload_catalog\(\)|\bcatalog_cache::preset_ball\(")


def code(path):
    """The file's lines that are not comments."""
    return [l for l in path.read_text().splitlines() if not l.lstrip().startswith("//")]


def test_only_the_resolver_builds_a_preset_ball():
    files = sorted(SRC.rglob("*.rs"))
    assert len(files) > 20, files
    elsewhere = [
        f"{f.relative_to(SRC).as_posix()}: {line.strip()}"
        for f in files
        if f.relative_to(SRC).as_posix() not in RESOLVERS
        for line in code(f)
        if BUILDS.search(line)
    ]
    assert not elsewhere, elsewhere
    assert RESOLVERS <= {f.relative_to(SRC).as_posix() for f in files}, "a resolver moved?"
