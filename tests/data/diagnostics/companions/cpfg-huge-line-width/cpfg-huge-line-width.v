initial line width: 1e300
