//! Layer 4: Klincsek's dynamic program over a polygon (G. T. Klincsek,
//! *Minimal triangulations of polygonal domains*, Annals of Discrete
//! Mathematics 9, 1980), generic in the objective.
