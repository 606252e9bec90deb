ignore: +-
consider: AB
ω: F
