# A table for fixture_rows/ whose last row allows more than its files include (self_test.cmake).
set(layers low mid high)
set(uses_low low/)
set(outside_low none)
set(uses_mid low/ mid/)
set(outside_mid none)
set(uses_high low/ mid/ high/)
set(outside_high gl)
