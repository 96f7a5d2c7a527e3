"""Reading packs: the loader (folders and zips, overlays, filters), pack.mcmeta, text and JSON
files, function tags, and the release table."""
