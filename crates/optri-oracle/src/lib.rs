//! Test oracles for optri.
