!> The element fields of the DIS_CHOC springs (SIEF_ELGA, VARI_ELGA; element_spring_fields)
!> at a converged state, stored with the instant in the result (analysis_result).
!>
!> Element frame of a SEG2 discrete, as Code_Aster builds it: x from node 1 to node 2, y and
!> z by the roll angle of ORIENTATION (ANGL_VRIL, or the third nautical angle) in 3D
!> (element_discrete segment_rotation), y = z x x in 2D. The force on node 2 and the
!> relative displacement u2 - u1 are turned into that frame; the normal gap is the one the
!> contact law decides the status with (element_dis_choc dis_choc_seg2_gap).
module spring_results
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_INTERNAL
    use strings, only: to_text
    use model_types, only: ELEM_DIS_T_SEG2, ELEM_2D_DIS_T_SEG2
    use model_material, only: material_of_cell
    use model_cara_elem, only: ORIENT_ANGL_VRIL, ORIENT_ANGL_NAUT
    use element_discrete, only: segment_rotation, segment_rotation_2d
    use element_dis_choc, only: dis_choc_seg2_gap
    use element_spring_fields, only: dis_choc_fields, DIS_CHOC_N_VARI
    use assembly_system, only: structure_t, spring_response, MAX_ELEMENT_DOFS
    use analysis_result, only: result_concept_t, result_store_spring_fields
    implicit none
    private

    public :: store_spring_fields, spring_fields_at

contains

    !> Computes the spring fields at u and stores them with the last stored instant of res
    !> (its springs are res%spring_cell).
    !>  st : out, element failures naming the cell
    subroutine store_spring_fields(s, u, res, st)
        type(structure_t), intent(in) :: s
        real(dp), intent(in) :: u(:)
        type(result_concept_t), intent(inout) :: res
        type(status_t), intent(out) :: st
        real(dp), allocatable :: sief(:, :), vari(:, :)
        integer(i4) :: ndim
        call spring_fields_at(s, res%spring_cell, u, ndim, sief, vari, st)
        if (st%failed()) return
        call result_store_spring_fields(res, ndim, sief, vari)
    end subroutine store_spring_fields

    !> SIEF_ELGA and VARI_ELGA of DIS_CHOC SEG2 springs at displacements u.
    !>  springs : in, the spring cells
    !>  ndim    : out, 3 (DIS_T) or 2 (2D_DIS_T); 3 when there is no spring
    !>  sief    : out, (3, size(springs)) N VY VZ;  vari : out, (DIS_CHOC_N_VARI, ...)
    !>  st      : out, STATUS_INTERNAL for a cell that is no SEG2 discrete with DIS_CONTACT
    !>            material (structure_check refuses those before an analysis); element
    !>            failures naming the cell
    subroutine spring_fields_at(s, springs, u, ndim, sief, vari, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: springs(:)
        real(dp), intent(in) :: u(:)
        integer(i4), intent(out) :: ndim
        real(dp), allocatable, intent(out) :: sief(:, :), vari(:, :)
        type(status_t), intent(out) :: st
        real(dp) :: ue(MAX_ELEMENT_DOFS), force2(3), fn, frame(3, 3), force(3), rel(3), gap
        real(dp) :: x(3, 2), x2(2, 2)
        integer(i4) :: k, c, n, m, p0
        logical :: closed
        allocate (sief(3, size(springs)), vari(DIS_CHOC_N_VARI, size(springs)), source=0.0_dp)
        ndim = 3
        do k = 1, size(springs)
            c = springs(k)
            m = material_of_cell(s%materials, c)
            if (m == 0) then
                call missing(c, st)
                return
            end if
            if (.not. s%materials%materials(m)%has_dis_contact) then
                call missing(c, st)
                return
            end if
            select case (s%model%element(c))
            case (ELEM_DIS_T_SEG2)
                ndim = 3
            case (ELEM_2D_DIS_T_SEG2)
                ndim = 2
            case default
                call missing(c, st)
                return
            end select
            p0 = s%mesh%cell_ptr(c)
            x = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + 1))
            call spring_response(s, c, u, ue, n, force2, closed, fn, st)
            if (st%ok()) call element_frame(s, c, ndim, x, frame, st)
            if (st%failed()) return
            force = matmul(frame, force2)
            rel = 0.0_dp
            rel(1:ndim) = ue(ndim + 1:2 * ndim) - ue(1:ndim)
            rel = matmul(frame, rel)
            associate (dc => s%materials%materials(m)%dis_contact)
                if (ndim == 3) then
                    call dis_choc_seg2_gap(3_i4, x, ue(1:n), dc%dist_1, dc%dist_2, gap)
                else
                    x2 = x(1:2, :)               ! contiguous: no array temporary
                    call dis_choc_seg2_gap(2_i4, x2, ue(1:n), dc%dist_1, dc%dist_2, gap)
                end if
            end associate
            call dis_choc_fields(ndim, closed, gap, force, rel, sief(:, k), vari(:, k))
        end do
    contains
        subroutine missing(cell, err)
            integer(i4), intent(in) :: cell
            type(status_t), intent(out) :: err
            call set_error(err, STATUS_INTERNAL, 'spring fields: cell number ' // &
                to_text(cell) // ' is no SEG2 discrete with a DIS_CONTACT material')
        end subroutine missing
    end subroutine spring_fields_at

    !> Rows = the element axes in global components (3 x 3; in 2D the 2 x 2 block, zeros
    !> elsewhere).
    subroutine element_frame(s, c, ndim, x, frame, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c, ndim
        real(dp), intent(in) :: x(3, 2)
        real(dp), intent(out) :: frame(3, 3)
        type(status_t), intent(out) :: st
        real(dp) :: roll, r2(2, 2)
        frame = 0.0_dp
        if (ndim == 2) then
            call segment_rotation_2d(x(1:2, 1), x(1:2, 2), r2, st)
            frame(1:2, 1:2) = r2
            return
        end if
        roll = 0.0_dp
        if (s%cara%orientation(c) == ORIENT_ANGL_VRIL) roll = s%cara%orientation_values(1, c)
        if (s%cara%orientation(c) == ORIENT_ANGL_NAUT) roll = s%cara%orientation_values(3, c)
        call segment_rotation(x(:, 1), x(:, 2), roll, frame, st)
    end subroutine element_frame

end module spring_results
