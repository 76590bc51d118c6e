//! Reading point sets and writing triangulations and graphs.
