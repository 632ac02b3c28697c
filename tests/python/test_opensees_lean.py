"""`import poundfe.opensees` loads the lean extension _opensees alone: no
deal.II is mapped into the process (its /proc/self/maps), and the full
module poundfe still works beside it, imported first or second, each
extension with its own interpreter state (the same script's numbers through
poundfe.opensees and through poundfe.command("opensees") agree exactly).
poundfe.opensees.OpenSeesError pickles without loading deal.II, and a
recorder's write error when Python exits is printed once as one.

Each case runs in a fresh interpreter (a subprocess): what a process has
mapped cannot be unloaded."""

import json
import os
import shutil
import tempfile
import subprocess
import sys
import textwrap

import poundfe  # the package alone: nothing compiled is loaded here

from common import ROOT, TestCase

PACKAGE_DIRECTORY = os.path.dirname(os.path.dirname(os.path.abspath(poundfe.__file__)))

# A linear spring under a static load: u = P / k = 10 / 4 = 2.5 exactly.
SPRING = textwrap.dedent("""
    ops.wipe()
    ops.model('basic', '-ndm', 1, '-ndf', 1)
    ops.node(1, 0.0); ops.node(2, 1.0); ops.fix(1, 1)
    ops.uniaxialMaterial('Elastic', 1, 4.0)
    ops.element('zeroLength', 1, 1, 2, '-mat', 1, '-dir', 1)
    ops.timeSeries('Linear', 1); ops.pattern('Plain', 1, 1); ops.load(2, 10.0)
    ops.system('BandGeneral'); ops.numberer('Plain'); ops.constraints('Plain')
    ops.integrator('LoadControl', 1.0); ops.algorithm('Linear'); ops.analysis('Static')
    assert ops.analyze(1) == 0
    """)

DEAL_II_MAPPED = "sum('libdeal' in line for line in open('/proc/self/maps'))"


def python_process(code):
    """Runs `code` in a fresh python3 with the package these tests import."""
    environment = dict(os.environ, PYTHONPATH=PACKAGE_DIRECTORY)
    return subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=environment,
                          capture_output=True, text=True, timeout=600)


def run_python(code):
    """Runs `code` in a fresh python3 with the package these tests import: its stdout."""
    done = python_process(code)
    if done.returncode != 0:
        raise AssertionError(f"python3 exited {done.returncode}:\n{done.stderr}")
    return done.stdout


class LeanImportTest(TestCase):
    def test_opensees_maps_no_deal_ii(self):
        code = "import poundfe.opensees as ops\n" + SPRING + textwrap.dedent(f"""
            import json
            print(json.dumps([ops.nodeDisp(2, 1), {DEAL_II_MAPPED}]))
            """)
        displacement, mapped = json.loads(run_python(code))
        self.assertEqual(displacement, 2.5)  # 10 / 4, exact in binary
        self.assertEqual(mapped, 0, "import poundfe.opensees mapped deal.II")

    def test_full_module_loads_deal_ii_at_its_first_name(self):
        code = textwrap.dedent(f"""
            import json
            import poundfe
            before = {DEAL_II_MAPPED}
            poundfe.InputError
            print(json.dumps([before, {DEAL_II_MAPPED}]))
            """)
        before, after = json.loads(run_python(code))
        self.assertEqual(before, 0)
        self.assertGreater(after, 0)

    def both_modules(self, opensees_first):
        """poundfe.opensees's spring and the same spring as a Tcl script run by
        poundfe.command("opensees"), with the two modules imported in the given
        order: (Python's displacement, the command's, the recorder's file)."""
        imports = ["import poundfe.opensees as ops", "import poundfe"]
        if not opensees_first:
            imports.reverse()
        code = "\n".join(imports) + "\n" + textwrap.dedent("""
            import json, os, tempfile
            poundfe.read('input/two-buildings.prm')  # the full module's core, loaded
            directory = tempfile.mkdtemp()
            script = os.path.join(directory, 'spring.tcl')
            with open(script, 'w') as f:
                f.write('''model basic -ndm 1 -ndf 1
            node 1 0.0; node 2 1.0; fix 1 1
            uniaxialMaterial Elastic 1 4.0
            element zeroLength 1 1 2 -mat 1 -dir 1
            timeSeries Linear 1; pattern Plain 1 1 { load 2 10.0 }
            system BandGeneral; numberer Plain; constraints Plain
            integrator LoadControl 1.0; algorithm Linear; analysis Static
            recorder Node -file ''' + os.path.join(directory, 'tcl.out') + ''' -node 2 -dof 1 disp
            analyze 1
            ''')
            """) + SPRING + textwrap.dedent("""
            python_displacement = ops.nodeDisp(2, 1)
            status = poundfe.command('opensees', script)
            ops.analyze(1)  # the Python domain is still its own after the command's run
            with open(os.path.join(directory, 'tcl.out')) as f:
                recorded = f.read().split()
            print(json.dumps([python_displacement, ops.nodeDisp(2, 1), status, recorded]))
            """)
        return json.loads(run_python(code))

    def test_both_modules_in_either_order(self):
        for opensees_first in (True, False):
            with self.subTest(opensees_first=opensees_first):
                first, second, status, recorded = self.both_modules(opensees_first)
                self.assertEqual(status, 0)
                self.assertEqual(first, 2.5)
                self.assertEqual(second, 5.0)  # LoadControl 1.0: load factor 2 at the second step
                self.assertEqual([float(v) for v in recorded], [2.5])


class OpenSeesErrorTest(TestCase):
    def test_pickles_without_deal_ii(self):
        code = textwrap.dedent(f"""
            import json, pickle
            import poundfe.opensees as ops
            ops.wipe()
            try:
                ops.node(1, 0.0)
            except ops.OpenSeesError as error:
                copy = pickle.loads(pickle.dumps(error))
                print(json.dumps([type(copy).__module__ + '.' + type(copy).__qualname__,
                                  type(copy) is ops.OpenSeesError, str(copy) == str(error),
                                  [copy.command, copy.file, copy.line] ==
                                  [error.command, error.file, error.line],
                                  {DEAL_II_MAPPED}]))
            """)
        name, same_type, same_message, same_attributes, mapped = json.loads(run_python(code))
        self.assertEqual(name, "poundfe.opensees.OpenSeesError")
        self.assertTrue(same_type and same_message and same_attributes)
        self.assertEqual(mapped, 0, "pickling OpenSeesError mapped deal.II")

    def exit_with_write_error(self, wipe):
        """A recorder of the spring whose temporary is a link to /dev/full
        (every write fails: ENOSPC), finished when Python exits or by a
        wipe the script catches: (the process, the files left)."""
        directory = tempfile.mkdtemp()
        path = os.path.join(directory, "disp.out")
        os.symlink("/dev/full", path + ".tmp")
        spring = SPRING.replace("assert ops.analyze(1) == 0",
                                f"ops.recorder('Node', '-file', {path!r}, '-node', 2, '-dof', 1, "
                                "'disp')\nassert ops.analyze(1) == 0")
        code = "import poundfe.opensees as ops\n" + spring + textwrap.dedent("""
            if WIPE:
                try:
                    ops.wipe()
                except ops.OpenSeesError as error:
                    print('caught:', error)
            """).replace("WIPE", str(wipe))
        done = python_process(code)
        # the analysis's warning (no `test` given) aside
        done.stderr = "".join(line for line in done.stderr.splitlines(keepends=True)
                              if not line.startswith("WARNING analysis Static"))
        left = os.listdir(directory)  # the failed temporary (the link) is removed too
        shutil.rmtree(directory)
        return done, left, path

    def test_write_error_at_exit_printed_once(self):
        done, left, path = self.exit_with_write_error(wipe=False)
        error = (f"recorder 0: disk full: cannot write {path}: No space left on device "
                 "(its lines up to time 1)")
        self.assertEqual(done.stderr, f"poundfe.opensees.OpenSeesError: {error}\n")
        self.assertEqual(done.returncode, 0)  # Python's: an atexit function cannot change it
        self.assertEqual(left, [])

    def test_write_error_at_a_caught_wipe_not_again_at_exit(self):
        done, left, path = self.exit_with_write_error(wipe=True)
        self.assertRegex(done.stdout, r"^caught: wipe: recorder 0: disk full: cannot write "
                         r".*\(its lines up to time 1\) \(<string>, line \d+\)\n$")
        self.assertEqual(done.stderr, "")
        self.assertEqual(done.returncode, 0)
        self.assertEqual(left, [])
