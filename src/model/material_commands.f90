!> Command handlers of materials: DEFI_MATERIAU and AFFE_MATERIAU (doc/deck-language.md).
module material_commands
    use kinds, only: dp, i4
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: to_text
    use deck_concept, only: concept_t, concept_display_name
    use deck_command, only: command_t, keyword_set_t, concept_ref_t
    use deck_value, only: value_t, value_list_t, unpack_value, VK_INT, VK_REAL, VK_BOOL, &
        VK_STR, VK_TUPLE, VK_LIST, VK_CONCEPT
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t
    use mesh_concept, only: mesh_concept_t
    use mesh_command_support, only: relocate_error, group_cells, all_cells
    use model_concept, only: model_concept_t
    use model_material, only: material_t, material_field_init, assign_material, behaviour_t, &
        material_value_t, add_behaviour, has_behaviour, behaviour_names, VALUE_NUMBERS, &
        VALUE_TEXTS, VALUE_FUNCTIONS
    use model_material_merge, only: merge_materials
    use material_concept, only: material_concept_t, material_field_concept_t
    use function_concept, only: function_concept_t
    use varc_commands, only: affe_varc_occurrences
    implicit none
    private

    public :: run_defi_materiau, run_affe_materiau

    !> An empty list: no value kind.
    integer, parameter :: VK_NONE_FOUND = -1

contains

    !> DEFI_MATERIAU: every behaviour of Code_Aster's catalog is kept as data (the values
    !> the deck gives, the catalog's defaults); ELAS (E and NU, or K and MU, or CELE_P,
    !> CELE_S and RHO) and DIS_CONTACT are decoded for the elements. MATER (reuse) starts
    !> from an existing material: a behaviour it has already is replaced.
    !>  result : out, a material_concept_t
    !>  st     : out, located at the keyword: E <= 0, NU outside (-1, 0.5)
    subroutine run_defi_materiau(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(material_concept_t), allocatable :: mc
        integer(i4) :: f
        allocate (mc)
        if (cmd%has('MATER')) then
            call base_material(cmd, mc%material, st)
            if (st%failed()) return
        end if
        do f = 1, cmd%nfactor
            call keep_behaviour(cmd%occurrence(cmd%factors(f)%name, 1), mc%material, st)
            if (st%failed()) return
        end do
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
        call ctx%write_mess('    behaviours: ' // behaviour_names(mc%material))
        call move_alloc(mc, result)
    end subroutine run_defi_materiau

    ! MATER: the material DEFI_MATERIAU completes (its behaviours, ELAS and DIS_CONTACT).
    subroutine base_material(cmd, mat, st)
        type(command_t), intent(in) :: cmd
        type(material_t), intent(inout) :: mat
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        call cmd%get_concept('MATER', p, st)
        if (st%failed()) return
        select type (p)
        type is (material_concept_t)
            mat = p%material
        class default
            call cmd%error_at('MATER', 'expected a material (mater), got ' // p%type_name(), st)
        end select
    end subroutine base_material

    !> Keeps one behaviour (a factor keyword's occurrence) as data: each keyword with its
    !> numbers, texts or concepts. A behaviour the material has already (MATER) is replaced.
    subroutine keep_behaviour(occ, mat, st)
        type(keyword_set_t), intent(in) :: occ
        type(material_t), intent(inout) :: mat
        type(status_t), intent(out) :: st
        type(behaviour_t) :: b
        integer :: k
        b%name = occ%scope
        allocate (b%values(occ%n))
        do k = 1, occ%n
            call keep_value(occ, occ%items(k)%name, b%values(k), st)
            if (st%failed()) return
        end do
        if (has_behaviour(mat, b%name)) mat%behaviours = pack(mat%behaviours, &
            [(mat%behaviours(k)%name /= b%name, k = 1, size(mat%behaviours))])
        call add_behaviour(mat, b)
    end subroutine keep_behaviour

    ! One keyword's value(s): numbers (integers as reals), texts or concepts.
    subroutine keep_value(occ, key, value, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(material_value_t), intent(out) :: value
        type(status_t), intent(out) :: st
        type(value_t) :: v
        type(value_list_t) :: list
        type(concept_ref_t), allocatable :: refs(:)
        integer :: kind, k
        value%key = key
        v = occ%get_value(key)
        kind = v%kind
        if (kind == VK_TUPLE .or. kind == VK_LIST) then
            list = unpack_value(v)
            kind = VK_NONE_FOUND
            if (size(list%items) > 0) kind = list%items(1)%kind
        end if
        select case (kind)
        case (VK_INT, VK_REAL, VK_BOOL)
            value%kind = VALUE_NUMBERS
            call occ%get_reals(key, value%numbers, st)
        case (VK_STR)
            value%kind = VALUE_TEXTS
            call occ%get_texts(key, value%texts, st)
        case (VK_CONCEPT)
            call occ%get_concepts(key, refs, st)
            if (st%failed()) return
            value%kind = VALUE_FUNCTIONS
            allocate (value%functions(size(refs)), value%texts(size(refs)))
            do k = 1, size(refs)
                value%texts(k)%s = concept_display_name(refs(k)%ptr)
                select type (p => refs(k)%ptr)
                class is (function_concept_t)
                    value%functions(k)%ptr => p
                class default
                    value%kind = VALUE_TEXTS      ! a table ...: kept by its name
                end select
            end do
        case default
            value%kind = VALUE_NUMBERS        ! an empty list, or a value of no use as data
            allocate (value%numbers(0))
        end select
    end subroutine keep_value

    !> ELAS: E and NU, or the bulk and shear moduli K and MU (E = 9 K MU / (3 K + MU),
    !> NU = (3 K - 2 MU) / (2 (3 K + MU))), or the wave speeds CELE_P and CELE_S with RHO
    !> (MU = RHO CELE_S**2, LAMBDA = RHO CELE_P**2 - 2 MU): Code_Aster U4.43.01, ELAS.
    subroutine read_elas(occ, mat, st)
        type(keyword_set_t), intent(in) :: occ
        type(material_t), intent(inout) :: mat
        type(status_t), intent(out) :: st
        real(dp) :: k, mu, cp, cs, lambda, ratio
        character(len=:), allocatable :: key
        mat%has_elas = .true.
        mat%elas%has_rho = occ%has('RHO')
        if (mat%elas%has_rho) call occ%get_real('RHO', mat%elas%rho, st)
        if (st%failed()) return
        key = 'E'
        if (occ%has('E')) then
            call occ%get_real('E', mat%elas%e, st)
            if (st%ok()) call occ%get_real('NU', mat%elas%nu, st)
        else if (occ%has('K')) then
            key = 'K'
            call occ%get_real('K', k, st)
            if (st%ok()) call occ%get_real('MU', mu, st)
            if (st%failed()) return
            if (.not. (k > 0.0_dp .and. mu > 0.0_dp)) then
                call occ%error_at('K', 'the bulk and shear moduli K and MU must be > 0 ' // &
                    '(got K = ' // to_text(k) // ', MU = ' // to_text(mu) // ')', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
            ratio = mu / k
            mat%elas%e = 9.0_dp / (3.0_dp / mu + 1.0_dp / k)
            mat%elas%nu = (3.0_dp - 2.0_dp * ratio) / (2.0_dp * (3.0_dp + ratio))
        else
            key = 'CELE_P'
            call occ%get_real('CELE_P', cp, st)
            if (st%ok()) call occ%get_real('CELE_S', cs, st)
            if (st%failed()) return
            if (.not. (mat%elas%rho > 0.0_dp .and. cs > 0.0_dp .and. &
                       cp**2 > 4.0_dp / 3.0_dp * cs**2)) then
                call occ%error_at('CELE_P', 'wave speeds need RHO > 0, CELE_S > 0 and ' // &
                    'CELE_P > 2 CELE_S / sqrt(3) (a positive bulk modulus; got RHO = ' // &
                    to_text(mat%elas%rho) // ', CELE_P = ' // to_text(cp) // ', CELE_S = ' // &
                    to_text(cs) // ')', st, code=STATUS_MODEL_ERROR)
                return
            end if
            mu = mat%elas%rho * cs**2
            lambda = mat%elas%rho * (cp**2 - 2.0_dp * cs**2)
            mat%elas%e = mu * ((3.0_dp * lambda + 2.0_dp * mu) / (lambda + mu))
            mat%elas%nu = lambda / (2.0_dp * (lambda + mu))
        end if
        if (st%failed()) return
        if (.not. mat%elas%e > 0.0_dp) then
            call occ%error_at(key, "Young's modulus must be > 0 (got " // &
                              to_text(mat%elas%e) // ')', st, code=STATUS_MODEL_ERROR)
            return
        end if
        if (mat%elas%nu <= -1.0_dp .or. mat%elas%nu >= 0.5_dp) then
            if (key == 'E') key = 'NU'
            call occ%error_at(key, "Poisson's ratio must be in (-1, 0.5) (got " // &
                              to_text(mat%elas%nu) // ')', st, code=STATUS_MODEL_ERROR)
            return
        end if
    end subroutine read_elas

    subroutine read_dis_contact(occ, mat, st)
        type(keyword_set_t), intent(in) :: occ
        type(material_t), intent(inout) :: mat
        type(status_t), intent(out) :: st
        mat%has_dis_contact = .true.
        associate (dc => mat%dis_contact)
            ! COULOMB /= 0 is kept as data: a contact law that uses it stops (STAT_NON_LINE
            ! COMPORTEMENT, analysis_commands refuse_friction)
            call occ%get_real('COULOMB', dc%coulomb, st)
            if (st%failed()) return
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
        call affe_varc_occurrences(ctx, cmd, fc%mesh, fc%field%varc, st)
        if (st%failed()) return
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
