"""The release's numbers and files agree (CHANGELOG.md, "the version has one
source"): the C header's RAST_VERSION_MAJOR/MINOR/PATCH, the installed
package's metadata, rastrum.__version__ (the linked core's
rast_version_number) and the newest release heading of CHANGELOG.md; the
licence the metadata names and the file it ships; every relative link of
README.md resolving (mkdocs --strict checks the docs' own)."""

import importlib.metadata
import os
import re

import rastrum

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read(*parts):
    with open(os.path.join(ROOT, *parts), encoding="utf-8") as f:
        return f.read()


def header_version():
    text = read("csrc", "include", "rastrum.h")
    return ".".join(re.search(r"^#define RAST_VERSION_%s (\d+)\s*$" % k, text, re.M).group(1)
                    for k in ("MAJOR", "MINOR", "PATCH"))


def changelog_releases():
    """[(version, date)] of CHANGELOG.md's release headings, newest first."""
    return re.findall(r"^## \[(\d+\.\d+\.\d+)\] - (\d{4}-\d\d-\d\d)\s*$", read("CHANGELOG.md"), re.M)


def test_one_version_everywhere():
    v = header_version()
    assert importlib.metadata.version("rastrum") == v
    assert rastrum.__version__ == v
    assert changelog_releases()[0][0] == v


def test_the_version_is_written_only_in_the_header():
    pyproject = read("pyproject.toml")
    assert re.search(r'^dynamic = \[.*"version".*\]', pyproject, re.M)
    assert not re.search(r"^version\s*=", pyproject, re.M)


def test_changelog_has_unreleased_first_then_releases_newest_first():
    text = read("CHANGELOG.md")
    heads = re.findall(r"^## (.*)$", text, re.M)
    assert heads[0] == "[Unreleased]"
    versions = [tuple(int(p) for p in v.split(".")) for v, _ in changelog_releases()]
    assert versions and versions == sorted(versions, reverse=True) and len(set(versions)) == len(versions)
    assert len(heads) == 1 + len(versions), heads  # every other heading is a release


def test_licence_in_metadata_and_files():
    meta = importlib.metadata.metadata("rastrum")
    assert meta["License-Expression"] == "MIT"
    assert meta["Author"] == "the rastrum authors"
    assert "Programming Language :: Python :: 3.9" in meta.get_all("Classifier")
    licence = read("LICENSE")
    assert licence.startswith("MIT License") and "Copyright (c) 2026 the rastrum authors" in licence
    files = [f for f in importlib.metadata.files("rastrum") if f.name == "LICENSE"]
    assert files and files[0].read_text(encoding="utf-8") == licence


LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")


def anchors(markdown):
    """The anchors mkdocs' toc gives a page's headings (its slugify)."""
    out = set()
    for head in re.findall(r"^#+ (.*)$", re.sub(r"^```.*?^```", "", markdown, flags=re.S | re.M), re.M):
        slug = re.sub(r"[^\w\s-]", "", head.strip().lower())
        out.add(re.sub(r"[-\s]+", "-", slug).strip("-"))
    return out


def test_readme_links_resolve():
    text = re.sub(r"^```.*?^```", "", read("README.md"), flags=re.S | re.M)
    links = LINK.findall(text)
    assert len(links) >= 10
    for link in links:
        if re.match(r"[a-z]+:", link):
            continue  # a web address: not checked offline
        path, _, anchor = link.partition("#")
        target = os.path.join(ROOT, path) if path else os.path.join(ROOT, "README.md")
        assert os.path.exists(target), "README.md links to %s, which is not in the repository" % link
        if anchor:
            assert anchor in anchors(read(os.path.relpath(target, ROOT))), "README.md: no heading for %s" % link


def test_every_extra_says_what_it_is_for():
    """make test-py prints each extra's note (tools/extras.py) before installing it."""
    section = read("pyproject.toml").split("[project.optional-dependencies]")[1].split("\n[")[0]
    extras = re.findall(r"^([\w-]+) = \[", section, re.M)
    assert {"test", "gis", "compat-test", "dask"} <= set(extras), extras
    text = read("tools", "extras.py")
    for name in extras:
        assert '"%s":' % name in text, "tools/extras.py has no note for the extra %r" % name
