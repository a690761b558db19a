"""docs/cli/<command>.md cannot drift from the CLI: every flag that `rigidfold <command> --help`
lists (and each subcommand's, for vertex and string) appears on the command's page, every flag in
the page's flag tables is one the command takes, and every command has its page."""
import os
import re
import subprocess

import pytest

from conftest import SOURCE_DIR, cli_path

DOCS = os.path.join(SOURCE_DIR, "docs", "cli")
FLAG = re.compile(r"(?<![\w-])--[a-z][a-z0-9-]*")


def help_text(*args):
    r = subprocess.run([cli_path(), *args, "--help"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    return r.stdout


def subcommands(text):
    """Names under CLI11's "Subcommands:" heading."""
    parts = re.split(r"^subcommands:\s*$", text, maxsplit=1, flags=re.M | re.I)
    if len(parts) < 2:
        return []
    block = parts[1]
    return [m.group(1) for m in re.finditer(r"^\s{2}([a-z0-9][a-z0-9-]*)\b", block, re.M)]


def flags_of(command):
    text = help_text(command)
    flags = set(FLAG.findall(text))
    for sub in subcommands(text):
        flags |= set(FLAG.findall(help_text(command, sub)))
    flags.discard("--help")
    return flags


def commands():
    return sorted(subcommands(help_text()))


def pages():
    return sorted(f[:-3] for f in os.listdir(DOCS) if f.endswith(".md") and f != "README.md")


def test_every_command_has_a_page_and_every_page_a_command():
    assert commands() == pages()


@pytest.mark.parametrize("command", pages())
def test_page_lists_every_flag_and_only_the_commands_flags(command):
    with open(os.path.join(DOCS, command + ".md")) as f:
        page = f.read()
    taken = flags_of(command)
    on_page = set(FLAG.findall(page))
    assert not taken - on_page, f"docs/cli/{command}.md lacks {sorted(taken - on_page)}"
    # The flag tables: rows that start with a flag name this command must take.
    tabled = {FLAG.match(row[3:]).group(0) for row in page.splitlines() if row.startswith("| `--") and FLAG.match(row[3:])}
    assert not tabled - taken, f"docs/cli/{command}.md documents {sorted(tabled - taken)}, which `{command}` does not take"
