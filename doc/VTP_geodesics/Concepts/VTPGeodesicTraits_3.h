/*!
\ingroup PkgVTPGeodesicsConcepts
\cgalConcept

The concept `VTPGeodesicTraits_3` describes the geometric types and the single geometric operation
needed by `CGAL::VTP_geodesics::Geodesic_distance_solver` and
`CGAL::VTP_geodesics::compute_geodesic_distances()`.

The algorithm is intrinsic: the only information it takes from the embedding of the mesh is the
squared length of each edge. Each squared length is converted to `double` with `CGAL::to_double()`
once, when the solver is built, and all later computations use `double`.

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

/// @}

/// \name Operations
/// @{

/*!
returns a `Compute_squared_distance_3` function object.
*/
Compute_squared_distance_3 compute_squared_distance_3_object() const;

/// @}

}; /* end VTPGeodesicTraits_3 */
