"""Every case of checks/file_rules.json through the lab's writers (files.py's
write_atomically and replacing, and csvout.write_csv, which the report's
CSVs go through) and its bounded reader; then the case the table cannot
state: a link planted at the writer's temporary name is never followed.
Run: /usr/bin/python3 -m unittest discover -s lab/tests -p test_file_rules.py (CTest: lab_file_rules)."""

import json
import os
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path
from unittest import mock

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report import csvout, files  # noqa: E402

RULES = json.loads((Path(__file__).resolve().parents[2] / "checks" / "file_rules.json").read_text())
READ_LIMIT = 4096  # the limit the reader cases are read with
IS_ROOT = os.geteuid() == 0


def write_with_write_atomically(target):
    files.write_atomically(target, "new")


def write_with_replacing(target):
    with files.replacing(target) as stream:
        stream.write("new")


def write_with_write_csv(target):
    csvout.write_csv(target, [], ["new"], [])


WRITERS = {"write_atomically": write_with_write_atomically, "replacing": write_with_replacing,
           "csvout.write_csv": write_with_write_csv}


def skip_reason(case):
    if case.get("root_only") and not IS_ROOT:
        return "needs root"
    if case.get("not_root") and IS_ROOT:
        return "root bypasses it"
    return None


def writer_setup(setup, folder):
    """The target for `setup` in `folder`, and a check of what must hold afterwards."""
    target, victim = folder / "target.csv", folder / "victim"

    def victim_kept():
        assert victim.read_text() == "precious", "the victim changed"

    if setup == "absent":
        return target, lambda: None
    if setup == "regular":
        target.write_text("old")
        return target, lambda: None
    if setup == "symlink_to_regular":
        victim.write_text("precious")
        target.symlink_to("victim")
        return target, lambda: (victim_kept(), _assert(target.is_symlink(), "the link was replaced"))
    if setup == "dangling_symlink":
        target.symlink_to("victim")
        return target, lambda: _assert(not victim.exists(), "the link was followed")
    if setup == "hardlink":
        victim.write_text("precious")
        os.link(victim, target)
        return target, victim_kept
    if setup == "fifo":
        os.mkfifo(target)
        return target, lambda: _assert(target.is_fifo(), "the FIFO was replaced")
    if setup == "char_device":
        subprocess.run(["mknod", str(target), "c", "1", "3"], check=True)
        return target, lambda: _assert(target.is_char_device(), "the device was replaced")
    if setup == "folder":
        target.mkdir()
        return target, lambda: _assert(not any(target.iterdir()), "something was written into the folder")
    if setup == "missing_folder":
        missing = folder / "missing"
        return missing / "target.csv", lambda: _assert(not missing.exists(), "the folder was made")
    if setup == "long_name":
        return folder / ("n" * 250), lambda: None
    if setup == "read_only_folder":
        locked = folder / "locked"
        locked.mkdir(mode=0o555)
        return locked / "target.csv", lambda: _assert(not any(locked.iterdir()), "a file was made")
    raise ValueError(f"no setup {setup}")


def _assert(condition, message):
    if not condition:
        raise AssertionError(message)


def reader_setup(setup, folder):
    path = folder / "input"
    if setup == "regular":
        path.write_text("ok\n")
    elif setup == "folder":
        path.mkdir()
    elif setup == "fifo":
        os.mkfifo(path)
    elif setup == "dev_zero":
        return Path("/dev/zero")
    elif setup == "oversized":
        with open(path, "wb") as stream:
            stream.truncate(READ_LIMIT + 1)
    elif setup != "absent":
        raise ValueError(f"no setup {setup}")
    return path


class FolderCase(unittest.TestCase):
    def fresh_folder(self):
        folder = Path(tempfile.mkdtemp(prefix="file_rules_py-"))

        def remove():
            for path in [folder, *folder.iterdir()]:
                if not path.is_symlink() and path.is_dir():
                    path.chmod(0o700)
            subprocess.run(["rm", "-rf", str(folder)], check=True)
        self.addCleanup(remove)
        return folder

    def no_temporary_left(self, folder):
        self.assertEqual([p.name for p in folder.iterdir() if p.name.endswith(".tmp")], [])


class WriterCases(FolderCase):
    def test_every_writer_case(self):
        for case in RULES["writer"]:
            for writer_name, writer in WRITERS.items():
                with self.subTest(case=case["name"], writer=writer_name):
                    reason = skip_reason(case)
                    if reason:
                        self.skipTest(reason)
                    folder = self.fresh_folder()
                    target, after = writer_setup(case["setup"], folder)
                    if case["expect"] == "written":
                        files.check_writable(target)
                        writer(target)
                        self.assertTrue(target.is_file() and not target.is_symlink())
                        self.assertIn("new", target.read_text())
                    else:
                        # The check before the run refuses it, and so does the writer itself.
                        with self.assertRaises(files.FileRefused) as checked:
                            files.check_writable(target)
                        self.assertIn(case["why"], str(checked.exception))
                        with self.assertRaises(files.FileRefused) as written:
                            writer(target)
                        self.assertIn(case["why"], str(written.exception))
                    after()
                    if folder.exists():
                        self.no_temporary_left(folder)

    def test_a_failed_write_leaves_the_old_file_and_no_temporary(self):
        folder = self.fresh_folder()
        target = folder / "target.csv"
        target.write_text("old")
        with self.assertRaises(RuntimeError):
            with files.replacing(target) as stream:
                stream.write("half")
                raise RuntimeError("the writer failed")
        self.assertEqual(target.read_text(), "old")
        self.no_temporary_left(folder)

    def test_a_link_planted_at_the_temporary_name_is_not_followed(self):
        folder = self.fresh_folder()
        (folder / "victim").write_text("precious")
        planted = folder / ".m.json.0123456789abcdef.tmp"
        planted.symlink_to("victim")
        real = files.secrets.token_hex
        drawn = iter(["0123456789abcdef"])
        with mock.patch.object(files.secrets, "token_hex", side_effect=lambda n: next(drawn, None) or real(n)) as draws:
            files.write_atomically(folder / "m.json", "new")
        self.assertGreaterEqual(draws.call_count, 2, "the planted name was not the first drawn")
        self.assertEqual((folder / "victim").read_text(), "precious")
        self.assertTrue(planted.is_symlink())
        self.assertEqual((folder / "m.json").read_text(), "new")
        self.assertFalse((folder / "m.json").is_symlink())


class ReaderCases(FolderCase):
    def test_every_reader_case(self):
        for case in RULES["reader"]:
            with self.subTest(case=case["name"]):
                reason = skip_reason(case)
                if reason:
                    self.skipTest(reason)
                path = reader_setup(case["setup"], self.fresh_folder())
                if case["expect"] == "read":
                    self.assertEqual(files.read_bytes(path, READ_LIMIT, "the input"), b"ok\n")
                else:
                    with self.assertRaises(files.InputError) as refused:
                        files.read_bytes(path, READ_LIMIT, "the input")
                    self.assertIn(case["why"], str(refused.exception))


if __name__ == "__main__":
    unittest.main()
