# A table for fixture_rows/ whose first row names a layer above it (self_test.cmake).
set(layers low mid high)
set(uses_low low/ high/)
set(outside_low none)
set(uses_mid low/ mid/)
set(outside_mid none)
set(uses_high low/ high/)
set(outside_high none)
