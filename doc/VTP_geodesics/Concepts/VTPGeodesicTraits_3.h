/*!
\ingroup PkgVTPGeodesicsConcepts
\cgalConcept

The concept `VTPGeodesicTraits_3` describes the geometric types and the two geometric operations
needed by `CGAL::VTP_geodesics::Geodesic_distance_solver` and
`CGAL::VTP_geodesics::compute_geodesic_distances()`.

The algorithm is intrinsic: the information it takes from the embedding of the mesh is the
squared length of each edge and the squared area of each face. The area could be derived from the
lengths, but for a nearly flat triangle (three almost collinear vertices) the lengths, once rounded,
determine its height only to about the square root of the rounding unit, while the area computed
from the points is accurate to the rounding unit; when the squared area is not finite or is zero
while the lengths say otherwise (overflow, underflow), the area is derived from the lengths.
Each value is converted to `double` with `CGAL::to_double()` once, when the solver is built, and all
later computations use `double`.

\cgalHasModel `CGAL::VTP_geodesics::Geodesic_traits_3<K>`
\cgalHasModel All the \cgal kernels
*/
class VTPGeodesicTraits_3
{
public:

/// \name Types
/// @{

/*!
The number type of the squared distances. It must be convertible to `double` with `CGAL::to_double()`.
*/
typedef unspecified_type FT;

/*!
The point type. It is the value type of the vertex point map.
*/
typedef unspecified_type Point_3;

/*!
Function object type that provides
`FT operator()(const Point_3& p, const Point_3& q)`,
which returns the squared Euclidean distance between `p` and `q`.
*/
typedef unspecified_type Compute_squared_distance_3;

/*!
Function object type that provides
`FT operator()(const Point_3& p, const Point_3& q, const Point_3& r)`,
which returns the squared area of the triangle `pqr`.
*/
typedef unspecified_type Compute_squared_area_3;

/// @}

/// \name Operations
/// @{

/*!
returns a `Compute_squared_distance_3` function object.
*/
Compute_squared_distance_3 compute_squared_distance_3_object() const;

/*!
returns a `Compute_squared_area_3` function object.
*/
Compute_squared_area_3 compute_squared_area_3_object() const;

/// @}

}; /* end VTPGeodesicTraits_3 */
