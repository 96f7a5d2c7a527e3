"""The pool datapack ships inside the distribution, as the package data of ``poolgame.datapack``
(mapped from the top-level ``datapack/`` folder), so ``dpemu shot`` finds it after any install; the game data files (``mcfunction_parser/gamedata/data``)
ship the same way."""
from setuptools import find_packages, setup

setup(
    packages=find_packages(include=["emulator*", "mcfunction_parser*", "poolgame*"]) + ["poolgame.datapack"],
    package_dir={"poolgame.datapack": "datapack"},
    # the VM's loop template: emulator.vm.variants renders smaller loops from it at run time
    package_data={"poolgame.datapack": ["**/*"], "mcfunction_parser.gamedata": ["data/*"], "emulator.vm": ["loop.py.in"]},
)
