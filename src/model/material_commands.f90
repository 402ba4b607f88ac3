!> Command handlers of materials: DEFI_MATERIAU and AFFE_MATERIAU (doc/deck-language.md).
module material_commands
    use kinds, only: dp, i4
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: to_text
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t, concept_ref_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t
    use mesh_concept, only: mesh_concept_t
    use mesh_command_support, only: relocate_error, group_cells, all_cells
    use model_concept, only: model_concept_t
    use model_material, only: material_t, material_field_init, assign_material
    use model_material_merge, only: merge_materials
    use material_concept, only: material_concept_t, material_field_concept_t
    implicit none
    private

    public :: run_defi_materiau, run_affe_materiau

contains

    !> DEFI_MATERIAU(ELAS=_F(E, NU, RHO), DIS_CONTACT=_F(RIGI_NOR, RIGI_TAN, DIST_1, DIST_2,
    !> JEU, COULOMB, AMOR_NOR, AMOR_TAN)).
    !>  result : out, a material_concept_t
    !>  st     : out, located at the keyword: E <= 0, NU outside (-1, 0.5), COULOMB /= 0
    !>           (friction is not built yet: frictionless DIS_CHOC and DIS_CONTACT only)
    subroutine run_defi_materiau(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(material_concept_t), allocatable :: mc
        allocate (mc)
        if (cmd%count('ELAS') > 0) then
            call read_elas(cmd%occurrence('ELAS', 1), mc%material, st)
            if (st%failed()) return
            call ctx%write_mess('    ELAS E ' // to_text(mc%material%elas%e) // ' NU ' // &
                                to_text(mc%material%elas%nu))
        end if
        if (cmd%count('DIS_CONTACT') > 0) then
            call read_dis_contact(cmd%occurrence('DIS_CONTACT', 1), mc%material, st)
            if (st%failed()) return
            call ctx%write_mess('    DIS_CONTACT DIST_1 ' // &
                to_text(mc%material%dis_contact%dist_1) // ' DIST_2 ' // &
                to_text(mc%material%dis_contact%dist_2))
        end if
        call move_alloc(mc, result)
    end subroutine run_defi_materiau

    subroutine read_elas(occ, mat, st)
        type(keyword_set_t), intent(in) :: occ
        type(material_t), intent(inout) :: mat
        type(status_t), intent(out) :: st
        mat%has_elas = .true.
        call occ%get_real('E', mat%elas%e, st)
        if (st%failed()) return
        if (mat%elas%e <= 0.0_dp) then
            call occ%error_at('E', "Young's modulus must be > 0 (got " // &
                              to_text(mat%elas%e) // ')', st, code=STATUS_MODEL_ERROR)
            return
        end if
        call occ%get_real('NU', mat%elas%nu, st)
        if (st%failed()) return
        if (mat%elas%nu <= -1.0_dp .or. mat%elas%nu >= 0.5_dp) then
            call occ%error_at('NU', "Poisson's ratio must be in (-1, 0.5) (got " // &
                              to_text(mat%elas%nu) // ')', st, code=STATUS_MODEL_ERROR)
            return
        end if
        mat%elas%has_rho = occ%has('RHO')
        if (mat%elas%has_rho) call occ%get_real('RHO', mat%elas%rho, st)
    end subroutine read_elas

    subroutine read_dis_contact(occ, mat, st)
        type(keyword_set_t), intent(in) :: occ
        type(material_t), intent(inout) :: mat
        type(status_t), intent(out) :: st
        mat%has_dis_contact = .true.
        associate (dc => mat%dis_contact)
            call occ%get_real('COULOMB', dc%coulomb, st)
            if (st%failed()) return
            if (abs(dc%coulomb) > 0.0_dp) then
                call occ%error_at('COULOMB', 'friction is not built yet: parasol has ' // &
                    'frictionless DIS_CHOC and DIS_CONTACT only (COULOMB must be 0, got ' // &
                    to_text(dc%coulomb) // ')', st, code=STATUS_NOT_IMPLEMENTED)
                return
            end if
            dc%has_rigi_nor = occ%has('RIGI_NOR')
            if (dc%has_rigi_nor) call occ%get_real('RIGI_NOR', dc%rigi_nor, st)
            if (st%ok()) call occ%get_real('RIGI_TAN', dc%rigi_tan, st)
            if (st%ok()) call occ%get_real('DIST_1', dc%dist_1, st)
            if (st%ok()) call occ%get_real('DIST_2', dc%dist_2, st)
            dc%has_jeu = occ%given('JEU')
            if (st%ok()) call occ%get_real('JEU', dc%jeu, st)
            if (st%ok()) call occ%get_real('AMOR_NOR', dc%amor_nor, st)
            if (st%ok()) call occ%get_real('AMOR_TAN', dc%amor_tan, st)
        end associate
    end subroutine read_dis_contact

    !> AFFE_MATERIAU(MAILLAGE | MODELE, AFFE=_F(TOUT='OUI' | GROUP_MA, MATER=(A, ...))):
    !> the material of each cell (later occurrences override earlier ones); several
    !> materials in one MATER are merged (merge_materials).
    !>  result : out, a material_field_concept_t
    !>  st     : out, located at the keyword: a group missing in the mesh, a concept of the
    !>           wrong type, two materials of one MATER defining the same behaviour
    subroutine run_affe_materiau(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(material_field_concept_t), allocatable :: fc
        type(keyword_set_t) :: occ
        type(material_t) :: merged
        integer(i4), allocatable :: cells(:)
        integer(i4) :: i
        allocate (fc)
        call field_mesh(cmd, fc%mesh, st)
        if (st%failed()) return
        call material_field_init(fc%field, fc%mesh)
        do i = 1, cmd%count('AFFE')
            occ = cmd%occurrence('AFFE', i)
            if (occ%has('TOUT')) then
                cells = all_cells(fc%mesh)
            else
                call group_cells(occ, 'GROUP_MA', fc%mesh, cells, st)
                if (st%failed()) return
            end if
            call occurrence_material(occ, merged, st)
            if (st%failed()) return
            call assign_material(fc%field, cells, merged)
            call ctx%write_mess('    material ' // merged%name // ' on ' // &
                                to_text(size(cells, kind=i4)) // ' cells')
        end do
        call move_alloc(fc, result)
    end subroutine run_affe_materiau

    ! The mesh of MAILLAGE, else that of MODELE.
    subroutine field_mesh(cmd, mesh, st)
        type(command_t), intent(in) :: cmd
        type(mesh_t), intent(inout) :: mesh
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        character(len=:), allocatable :: key
        key = 'MODELE'
        if (cmd%has('MAILLAGE')) key = 'MAILLAGE'
        call cmd%get_concept(key, p, st)
        if (st%failed()) return
        select type (p)
        type is (mesh_concept_t)
            mesh = p%mesh
        type is (model_concept_t)
            mesh = p%mesh
        class default
            call cmd%error_at(key, 'expected a mesh or a model, got ' // p%type_name(), st)
        end select
    end subroutine field_mesh

    ! MATER of one occurrence: one material, or the merge of several.
    subroutine occurrence_material(occ, merged, st)
        type(keyword_set_t), intent(in) :: occ
        type(material_t), intent(out) :: merged
        type(status_t), intent(out) :: st
        type(concept_ref_t), allocatable :: refs(:)
        type(material_t), allocatable :: mats(:)
        integer(i4) :: k
        call occ%get_concepts('MATER', refs, st)
        if (st%failed()) return
        allocate (mats(size(refs)))
        do k = 1, size(refs)
            select type (p => refs(k)%ptr)
            type is (material_concept_t)
                mats(k) = p%material
                mats(k)%name = concept_display_name(p)
            class default
                call occ%error_at('MATER', 'expected a material (mater), got ' // &
                                  p%type_name(), st)
                return
            end select
        end do
        call merge_materials(mats, merged, st)
        call relocate_error(occ, 'MATER', st)
    end subroutine occurrence_material

end module material_commands
