# Doxygen input filter for the public headers (cmake/Doxyfile.in): the
# headers are written with plain C comments, and this turns them into
# Doxygen comments on the fly, so the reference documents what the headers
# say without a second comment syntax in them:
#  - the file's opening comment becomes the file's documentation, kept
#    verbatim (its tables and aligned lists are ASCII layouts);
#  - a comment starting in column 0 documents the declaration below it (a
#    ---- rule around its title is dropped);
#  - a comment after an enumerator or a #define documents that member.
# (Line for line: Doxygen's warnings name the header's own line numbers.)
1s|^/\*|/** \\verbatim|
1,/\*\//{
  /\*\//s|^\(.*\)\*/|\1\\endverbatim \\file */|
  b
}
# Rules of dashes around a title: /* ----, * ---- */.
s|^/\* -\{4,\}[ ]*$|/**|
s|^ \* -\{4,\}[ ]*\*/| */|
# A comment in column 0 documents what follows it.
s|^/\*\([^*]\)|/**\1|
# A comment after code on the same line documents that line's member
# (enumerators and #define constants; not #endif, #include, #if).
/^[ ]*#[ ]*\(endif\|include\|if\|ifdef\|ifndef\|else\)/b
s|^\([^/]*[^/ ][^/]*[ ]\)/\*\([^*]\)|\1/**<\2|
