#!/usr/bin/env python3
"""The usage blocks of the command-line guide (docs/cli.md) are the CLI's own: for
every command that `sherpa-cli --help` lists, the synopsis `sherpa-cli COMMAND --help`
prints (its lines up to the first blank one, without "usage: ") appears, line for
line, inside one of the page's fenced code blocks. Prints the block to paste where
one is missing or differs. Usage: check_docs_usage.py SHERPA_CLI PAGE.md"""
import subprocess
import sys


def run(cli, *args):
    r = subprocess.run([cli, *args], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{cli} {' '.join(args)} exited {r.returncode}: {r.stderr}")
    return r.stdout


def code_blocks(text):
    blocks, current = [], None
    for line in text.splitlines():
        if line.startswith("```"):
            if current is None:
                current = []
            else:
                blocks.append(current)
                current = None
        elif current is not None:
            current.append(line)
    return blocks


def contains(block, lines):
    n = len(lines)
    return any(block[i:i + n] == lines for i in range(len(block) - n + 1))


def main():
    cli, page = sys.argv[1], sys.argv[2]
    commands = []
    for line in run(cli, "--help").splitlines():
        if line.startswith("sherpa-cli "):
            name = line.split()[1]
            if name not in commands:
                commands.append(name)
    if len(commands) < 5:
        sys.exit(f"only {commands} found in sherpa-cli --help")
    with open(page, encoding="utf-8") as f:
        blocks = code_blocks(f.read())
    failed = []
    for name in commands:
        text = run(cli, name, "--help")
        if not text.startswith("usage: "):
            failed.append(f"{name}: --help does not start with 'usage: '")
            continue
        synopsis = text[len("usage: "):].split("\n\n")[0].splitlines()
        if not any(contains(b, synopsis) for b in blocks):
            failed.append(f"{name}: {page} has no code block with this synopsis:\n" +
                          "```\n" + "\n".join(synopsis) + "\n```")
    for f in failed:
        print(f)
    print(f"{len(commands) - len(failed)} of {len(commands)} commands' usage in {page}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
