angle increment: 30
#include "/etc/passwd"
