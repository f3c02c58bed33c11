/// @file pathology_list.h
/// @brief Every pathology plug-in, one line each: LUNGAR_PATHOLOGY(NAME) for `pathology::NAME_pathology()`, defined in
///        sim/pathology/NAME.cpp. The order is the help texts' and the docs' table's. Included by pathology.cpp only.
LUNGAR_PATHOLOGY(pneumothorax)
LUNGAR_PATHOLOGY(consolidation)
LUNGAR_PATHOLOGY(emphysema)
LUNGAR_PATHOLOGY(ards)
LUNGAR_PATHOLOGY(effusion)
