/*---------------------------------------------------------------------------*\
    roughWallInteraction's tests: a mesh mover of OpenFOAM-13 and -14 that
    translates the whole mesh at a constant velocity, so that every wall
    face moves at that velocity (the Lagrangian's Uf).  The project's
    OpenFOAM-13 and -14 are built without the mesh-motion libraries; this
    one file is all a test of a moving wall needs: the mover, and a mesh
    stitcher for a changing mesh without non-conformal patches (OpenFOAM's
    is in libfvMeshStitchers, not built either).  Load the library in
    controlDict's libs too: the stitcher is chosen before the mover.

    constant/dynamicMeshDict:
        mover
        {
            type        roughWallTranslatingMesh;
            libs        ("libroughWallTranslatingMesh.so");
            velocity    (-0.5 0 0);
        }

    SPDX-License-Identifier: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "fvMeshMover.H"
#include "fvMeshStitcher.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace fvMeshMovers
{

class roughWallTranslatingMesh
:
    public fvMeshMover
{
    //- The velocity of every point [m/s]
    const vector velocity_;

    //- The points at time 0
    const pointField points0_;

public:

    TypeName("roughWallTranslatingMesh");

    roughWallTranslatingMesh(fvMesh& mesh, const dictionary& dict)
    :
        fvMeshMover(mesh),
        velocity_(dict.lookup("velocity")),
        points0_(mesh.points())
    {}

    virtual bool solidBody() const
    {
        return true;
    }

    virtual bool update()
    {
        mesh().preChange();
        mesh().movePoints
        (
            points0_ + velocity_*mesh().time().value()
        );
        return true;
    }

    virtual void topoChange(const polyTopoChangeMap&)
    {}

    virtual void mapMesh(const polyMeshMap&)
    {}

    virtual void distribute(const polyDistributionMap&)
    {}
};

defineTypeNameAndDebug(roughWallTranslatingMesh, 0);
addToRunTimeSelectionTable(fvMeshMover, roughWallTranslatingMesh, fvMesh);

} // End namespace fvMeshMovers


namespace fvMeshStitchers
{

class roughWallTranslatingMesh
:
    public fvMeshStitcher
{
    virtual bool changing() const
    {
        return true;
    }

    // Non-conformal patches only: this mesh has none

    virtual void conformCorrectMeshPhi(surfaceScalarField&)
    {
        NotImplemented;
    }

    virtual void createNonConformalCorrectMeshPhiGeometry
    (
        surfaceLabelField::Boundary&,
        surfaceVectorField&,
        surfaceVectorField&
    )
    {
        NotImplemented;
    }

    virtual void unconformCorrectMeshPhi
    (
        const surfaceLabelField::Boundary&,
        surfaceVectorField&,
        surfaceVectorField&,
        surfaceScalarField&
    )
    {
        NotImplemented;
    }

public:

    TypeName("roughWallTranslatingMesh");

    explicit roughWallTranslatingMesh(fvMesh& mesh)
    :
        fvMeshStitcher(mesh)
    {}
};

defineTypeNameAndDebug(roughWallTranslatingMesh, 0);
addToRunTimeSelectionTable(fvMeshStitcher, roughWallTranslatingMesh, fvMesh);

} // End namespace fvMeshStitchers
} // End namespace Foam
