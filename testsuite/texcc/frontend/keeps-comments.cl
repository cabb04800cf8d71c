// Comments, blank lines and formatting are kept as the user wrote them.
// RUN: texcc-fe %s | FileCheck %s

/* A block comment
   over two lines. */
float   spaced ( float   x )   // trailing comment
{
    return x;   /* inside */
}
// CHECK: {{^}}/* A block comment
// CHECK-NEXT: {{^}}   over two lines. */
// CHECK-NEXT: {{^}}TEXCC_FN float   keeps_comments_spaced (TEXCC_CTX_PARAM, float   x )   // trailing comment
// CHECK-NEXT: {{^}}{
// CHECK-NEXT: {{^}}    return x;   /* inside */
// CHECK-NEXT: {{^}}}
