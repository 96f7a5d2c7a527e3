"""Families of vanilla ids: the dye colours and wood types that block and item ids are made of
(``white_wool``, ``oak_button`` ...), one list each for every module that spells such ids out."""
COLOURS = ("white orange magenta light_blue yellow lime pink gray light_gray cyan purple blue brown "
           "green red black").split()
WOODS = "oak spruce birch jungle acacia dark_oak mangrove cherry pale_oak bamboo crimson warped".split()
