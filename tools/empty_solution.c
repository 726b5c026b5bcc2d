/* An empty solution: make check shows that every exercise refuses it
   (its tests fail to link, or fail). */
typedef int empty_solution;
