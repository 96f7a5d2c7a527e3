"""The pool game's Python: the float64 reference of its physics (:mod:`.physics`) and the shot driver
behind ``dpemu shot``. The generic emulator never imports this package."""
