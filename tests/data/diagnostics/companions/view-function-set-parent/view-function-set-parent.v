angle increment: 30
function set: ../../../../../../../../../../etc/passwd
