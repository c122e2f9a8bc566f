# doc/local.mk: the documentation that `make install` puts in $(docdir) (and the tarball
# carries): what `scn pov` writes and where POV-Ray differs, named by every .pov's header;
# and scn's noise, which the noisy patterns and bumps use (why their POV-Ray twins agree in
# look only).
dist_doc_DATA = doc/povray.md doc/noise.md
