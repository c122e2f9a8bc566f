# doc/local.mk: the documentation that `make install` puts in $(docdir) (and the tarball
# carries): what `scn pov` writes and where POV-Ray differs, named by every .pov's header.
dist_doc_DATA = doc/povray.md
