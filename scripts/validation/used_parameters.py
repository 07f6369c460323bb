"""Entries of the used_parameters.prm that every Particulate run writes into
its output folder, for the validation scripts next to this file."""
import os
import re
import sys


def used_value(folder, entry):
    """The value of the first 'set <entry> = ...' line in
    <folder>/used_parameters.prm (entry names are unique enough in the
    cases these scripts read); exits with a message when there is none."""
    with open(os.path.join(folder, "used_parameters.prm")) as f:
        for line in f:
            m = re.match(r"\s*set\s+" + re.escape(entry) + r"\s*=\s*(.*)", line)
            if m:
                return m.group(1).strip()
    sys.exit(f"{folder}/used_parameters.prm: no entry '{entry}'")
