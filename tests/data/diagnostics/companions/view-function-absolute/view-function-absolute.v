angle increment: 30
function: /etc/passwd
