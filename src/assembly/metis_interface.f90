!> C binding of the two METIS 5 entry points parasol uses (metis.h of Debian's libmetis-dev,
!> built with 32-bit idx_t; cmake/FindMETIS.cmake checks IDXTYPEWIDTH = 32).
!> METIS arrays are 0-based unless options(METIS_OPTION_NUMBERING) = 1; parasol keeps the C
!> numbering and converts in `renumbering`.
module metis_interface
    use, intrinsic :: iso_c_binding, only: c_int32_t
    implicit none
    private

    integer, parameter, public :: metis_idx = c_int32_t    !< idx_t (IDXTYPEWIDTH 32)
    integer, parameter, public :: METIS_NOPTIONS = 40      !< size of options[] (metis.h)
    integer, parameter, public :: METIS_OK = 1             !< rstatus_et METIS_OK
    !> 0-based index of METIS_OPTION_NUMBERING in options[] (moptions_et; add 1 in Fortran).
    integer, parameter, public :: METIS_OPTION_NUMBERING = 17

    public :: metis_setdefaultoptions, metis_nodend

    interface
        !> int METIS_SetDefaultOptions(idx_t *options): fills options[METIS_NOPTIONS].
        function metis_setdefaultoptions(options) bind(c, name='METIS_SetDefaultOptions')
            use, intrinsic :: iso_c_binding, only: c_int, c_int32_t
            integer(c_int32_t), intent(out) :: options(*)
            integer(c_int) :: metis_setdefaultoptions
        end function metis_setdefaultoptions

        !> int METIS_NodeND(idx_t *nvtxs, idx_t *xadj, idx_t *adjncy, idx_t *vwgt,
        !>                  idx_t *options, idx_t *perm, idx_t *iperm)
        !> Nested-dissection fill-reducing ordering; row i of the permuted matrix is row
        !> perm[i] of the original, iperm[perm[i]] = i. vwgt may be NULL (c_null_ptr).
        function metis_nodend(nvtxs, xadj, adjncy, vwgt, options, perm, iperm) &
            bind(c, name='METIS_NodeND')
            use, intrinsic :: iso_c_binding, only: c_int, c_int32_t, c_ptr
            integer(c_int32_t), intent(in) :: nvtxs
            integer(c_int32_t), intent(in) :: xadj(*), adjncy(*)
            type(c_ptr), value :: vwgt
            integer(c_int32_t), intent(in) :: options(*)
            integer(c_int32_t), intent(out) :: perm(*), iperm(*)
            integer(c_int) :: metis_nodend
        end function metis_nodend
    end interface

end module metis_interface
