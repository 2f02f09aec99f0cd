"""Import this module before SfePy, in every script that uses SfePy.

Debian's SfePy (sfepy/base/base.py, 2022.4) creates its configuration directory ~/.sfepy when it is
first imported, with a check and then a create:

    if not os.path.exists(sfepy_config_dir):
        os.makedirs(sfepy_config_dir)

On a machine where ~/.sfepy does not exist yet, two processes that import SfePy at the same moment
(ctest -j runs the SfePy tests side by side) can both see it missing; the slower makedirs then
raises FileExistsError and its script dies before doing anything (issue 34). Creating the directory
here with exist_ok=True, which is race-free, before SfePy's own check runs, means SfePy always
finds it. tests/fem/check_sfepy_first_run.py fails if a script in the tree imports SfePy without
importing this module first.
"""
import os
import sys

if 'sfepy' in sys.modules:
    raise ImportError('sfepy_ready must be imported before SfePy (SfePy was already imported)')

SFEPY_CONFIG_DIR = os.path.expanduser('~/.sfepy')
os.makedirs(SFEPY_CONFIG_DIR, exist_ok=True)
