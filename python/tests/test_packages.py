"""README's list of Debian packages is scripts/setup.sh's list (same names)."""
import pathlib
import re
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def setup_packages():
    text = (ROOT / "scripts" / "setup.sh").read_text()
    body = re.search(r"^packages=\((.*?)\)", text, re.M | re.S).group(1)
    return set(body.split())


def readme_packages():
    text = (ROOT / "README.md").read_text()
    para = re.search(r"`scripts/setup.sh` installs only the missing Debian packages \(`(.*?)`\)",
                     text, re.S).group(1)
    return set(para.split())


class Packages(unittest.TestCase):
    def test_readme_lists_what_setup_installs(self):
        self.assertEqual(readme_packages(), setup_packages())

    def test_the_notebook_packages_are_installed_by_setup(self):
        self.assertTrue({"python3-pandas", "python3-matplotlib", "python3-nbclient",
                         "python3-ipykernel", "python3-pip", "python3-wheel"} <= setup_packages())


if __name__ == "__main__":
    unittest.main()
